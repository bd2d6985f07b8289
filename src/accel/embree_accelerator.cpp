#include "accel/embree_accelerator.h"

#include <embree3/rtcore.h>

#include <chrono>
#include <cmath>
#include <stdexcept>
#include <string>

namespace lightpath {
namespace {

// The ignored primitive reaches the filter through the context (Embree's documented way to pass
// per-query data: a struct that begins with RTCIntersectContext).
struct IgnoringContext {
    RTCIntersectContext context;
    std::uint32_t ignored;
};

void ignoreOwnPrimitive(const RTCFilterFunctionNArguments* args) {
    const auto* context = reinterpret_cast<const IgnoringContext*>(args->context);
    for (unsigned i = 0; i < args->N; ++i) {
        if (args->valid[i] == 0) continue;
        if (RTCHitN_primID(args->hit, args->N, i) == context->ignored) args->valid[i] = 0;
    }
}

RTCRay embreeRay(const Ray& ray, float tFar) {
    RTCRay r{};
    r.org_x = ray.origin.x;
    r.org_y = ray.origin.y;
    r.org_z = ray.origin.z;
    r.dir_x = ray.direction.x;
    r.dir_y = ray.direction.y;
    r.dir_z = ray.direction.z;
    r.tnear = ray.tMin;
    // Embree accepts t <= tfar; ours is t < tMax.
    r.tfar = std::nextafter(tFar, 0.0f);
    r.mask = ~0u;
    r.flags = 0;
    return r;
}

IgnoringContext makeContext(std::uint32_t ignored) {
    IgnoringContext c{};
    rtcInitIntersectContext(&c.context);
    c.ignored = ignored;
    if (ignored != kNoPrimitive) c.context.filter = ignoreOwnPrimitive;
    return c;
}

}  // namespace

struct EmbreeScene::Handles {
    RTCDevice device = nullptr;
    RTCScene scene = nullptr;
};

EmbreeScene::EmbreeScene(std::span<const Triangle> triangles) : handles_(std::make_unique<Handles>()) {
    handles_->device = rtcNewDevice(nullptr);
    if (!handles_->device) {
        throw std::runtime_error("Embree: cannot create a device (error " + std::to_string(rtcGetDeviceError(nullptr)) + ")");
    }
    // The build, not the device (whose thread pool an application creates once).
    const auto started = std::chrono::steady_clock::now();
    handles_->scene = rtcNewScene(handles_->device);
    rtcSetSceneFlags(handles_->scene, RTC_SCENE_FLAG_CONTEXT_FILTER_FUNCTION);
    RTCGeometry mesh = rtcNewGeometry(handles_->device, RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(mesh, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                                 3 * sizeof(float), 3 * triangles.size()));
    auto* indices = static_cast<unsigned*>(rtcSetNewGeometryBuffer(mesh, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                                   3 * sizeof(unsigned), triangles.size()));
    for (std::size_t i = 0; i < triangles.size(); ++i) {
        const Vec3 corners[3] = {triangles[i].a, triangles[i].b, triangles[i].c};
        for (std::size_t k = 0; k < 3; ++k) {
            for (int axis = 0; axis < 3; ++axis) vertices[9 * i + 3 * k + static_cast<std::size_t>(axis)] = corners[k][axis];
            indices[3 * i + k] = static_cast<unsigned>(3 * i + k);
        }
    }
    rtcCommitGeometry(mesh);
    rtcAttachGeometry(handles_->scene, mesh);
    rtcReleaseGeometry(mesh);
    rtcCommitScene(handles_->scene);
    buildSeconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
}

EmbreeScene::~EmbreeScene() {
    rtcReleaseScene(handles_->scene);
    rtcReleaseDevice(handles_->device);
}

bool EmbreeScene::intersect(const Ray& ray, float tFar, std::uint32_t ignored, float& t, std::uint32_t& index) const {
    IgnoringContext context = makeContext(ignored);
    RTCRayHit rayHit{};
    rayHit.ray = embreeRay(ray, tFar);
    rayHit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(handles_->scene, &context.context, &rayHit);
    if (rayHit.hit.geomID == RTC_INVALID_GEOMETRY_ID) return false;
    t = rayHit.ray.tfar;
    index = rayHit.hit.primID;
    return true;
}

bool EmbreeScene::occluded(const Ray& ray, std::uint32_t ignored) const {
    IgnoringContext context = makeContext(ignored);
    RTCRay r = embreeRay(ray, ray.tMax);
    rtcOccluded1(handles_->scene, &context.context, &r);
    // Embree marks an occluded ray by setting tfar to -inf.
    return r.tfar < 0.0f;
}

}  // namespace lightpath
