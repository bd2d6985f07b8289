// scenes/lecture-room.toml for POV-Ray 3.7, for bench/vs_povray.sh: the same camera, sky, ambient
// light, two point lights, three balls, floor, six wall triangles and the Stanford bunny (a mesh2
// that bench/povray/obj_to_mesh2.py writes from scenes/meshes/stanford-bunny.obj, flat-shaded as
// lightpath shades an OBJ without normals).
//
// How lightpath's Whitted model (scenes/README.md) maps onto POV-Ray's finish:
//   ka Ia        pigment kd, finish ambient ka/kd (ka = kd in this scene, or 0), ambient_light Ia
//   kd (N.L)     pigment kd, finish diffuse 1
//   ks (H.N)^n   finish specular ks roughness 1/n (POV-Ray's specular is Blinn's half-vector lobe)
//   kr           finish reflection kr (constant, no Fresnel)
//   kt, ior      pigment transmit kt, interior ior
// Coordinates: lightpath is right-handed, POV-Ray left-handed: every z is negated, which shows the
// same image. --max-depth 5 (bounces after the camera ray) is max_trace_level 6. One difference
// remains: POV-Ray lets light through the glass ball (transmit) into its shadow; lightpath's
// shadow rays stop at it.
#version 3.7;
global_settings {
  assumed_gamma 1.0          // colours are linear, as in lightpath
  ambient_light rgb 0.15     // world.ambient
  max_trace_level 6
}
background { rgb <0.45, 0.62, 0.9> }

camera {
  perspective
  location <0, 1.7, -7>
  look_at <0, 1.1, 0>
  right x * image_width / image_height
  // lightpath's fov is vertical (45 degrees); POV-Ray's angle is horizontal.
  angle 2 * degrees(atan(tan(radians(45 / 2)) * image_width / image_height))
}

light_source { <1.5, 2.8, -3> color rgb <0.9, 0.85, 0.75> }   // key
light_source { <-2, 2.2, -5> color rgb 0.35 }                 // fill

#macro Matte(Colour)  // ka = kd
  texture { pigment { rgb Colour } finish { ambient 1 diffuse 1 } }
#end

sphere { <-1.6, 0.7, 0.5>, 0.7       // matte-ball
  texture { pigment { rgb <0.8, 0.4, 0.1> } finish { ambient 1 diffuse 1 specular 0.2 roughness 1 / 20 } }
}
sphere { <0.2, 0.9, 1.4>, 0.9        // mirror-ball: kd 0.05, ks 0.5, n 200, kr 0.8
  texture { pigment { rgb 0.05 } finish { ambient 0 diffuse 1 specular 0.5 roughness 1 / 200 reflection 0.8 } }
}
sphere { <1.5, 0.6, -1.0>, 0.6       // glass-ball: ks 0.4, n 300, kt 0.9, ior 1.5
  texture { pigment { rgbt <0, 0, 0, 0.9> } finish { ambient 0 diffuse 0 specular 0.4 roughness 1 / 300 } }
  interior { ior 1.5 }
}

#include "lecture-room-bunny.inc"
object { Bunny
  texture { pigment { rgb <0.75, 0.7, 0.6> } finish { ambient 1 diffuse 1 specular 0.15 roughness 1 / 30 } }
}

plane { y, 0 Matte(<0.45, 0.42, 0.38>) }   // floor

// Walls 3 high, two triangles each; the room is open at the top and toward the camera.
triangle { <-3, 0, 3>, <3, 0, 3>, <3, 3, 3> Matte(0.6) }          // back-wall
triangle { <-3, 0, 3>, <3, 3, 3>, <-3, 3, 3> Matte(0.6) }
triangle { <-3, 0, -3>, <-3, 0, 3>, <-3, 3, 3> Matte(<0.6, 0.12, 0.1>) }   // left-wall
triangle { <-3, 0, -3>, <-3, 3, 3>, <-3, 3, -3> Matte(<0.6, 0.12, 0.1>) }
triangle { <3, 0, 3>, <3, 0, -3>, <3, 3, -3> Matte(<0.1, 0.45, 0.45>) }    // right-wall
triangle { <3, 0, 3>, <3, 3, -3>, <3, 3, 3> Matte(<0.1, 0.45, 0.45>) }
