#pragma once
// A linear radiosity over each triangle patch solved on its own, for the gather of later bounces
// (radiosity.cpp, solve; RadiosityOptions::gatherGradients): the patch's own value B at its
// centroid plus a gradient fitted by weighted least squares to the values of the patches around
// it (those sharing a vertex with it: the same object and orientation, RadiosityMesh's welding),
// the reconstruction of finite-volume schemes (Barth and Jespersen 1989; weights 1/d^2 as in
// Mavriplis 2003's comparison of gradient reconstructions). Its mean over the triangle is its value
// at the centroid, B, so each element still sends exactly its own flux; unlike the plane through
// vertex means (each vertex the mean of the patches around it), it extrapolates: at a contact line,
// where the light keeps rising towards the edge and the vertex on the edge averages only the patches
// beside it, the plane through vertex means flattens the peak and this one follows its slope.
// The gradient is limited only so that no corner is negative (a limiter to the neighbours' range,
// Barth and Jespersen's, would clip the very peak at the edge that it is here to show).
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "integrators/radiosity_mesh.h"
#include "math/types.h"

namespace lightpath {

class PatchGradients {
public:
    // Finds, for each triangle patch that is a cluster of its own, the triangle patches sharing a
    // vertex with it and their centroids' offsets in its plane.
    explicit PatchGradients(const RadiosityMesh& mesh);

    // Per patch side 2 * patch + side, its corners' values (a, b, c) of the linear radiosity fitted
    // to `values` (per element 2 * cluster + side), and whether it has one (`fitted`); 0 where the
    // patch is not a triangle solved alone, or its lit neighbours leave the gradient undetermined
    // (the gather then reads the scaled Gouraud plane, as before). A neighbour side with no light
    // (black) is left out of the fit, as it is of the vertex means.
    void fit(std::span<const Rgb> values, std::vector<std::array<Rgb, 3>>& corners,
             std::vector<std::uint8_t>& fitted) const;

    // Patches with a neighbourhood to fit.
    std::size_t fittable() const { return patchStart_.size() - 1; }

private:
    struct Neighbour {
        std::uint32_t cluster;
        Vec2 offset;  // its centroid's, from the patch's, in the patch's plane
    };
    struct Fittable {
        std::uint32_t patch, cluster;
        std::array<Vec2, 3> corners;  // the corners' offsets from the centroid, in its plane
    };
    std::vector<Fittable> patches_;
    // Neighbours of patches_[i]: neighbours_[patchStart_[i] .. patchStart_[i + 1]).
    std::vector<std::uint32_t> patchStart_{0};
    std::vector<Neighbour> neighbours_;
    std::size_t patchCount_ = 0;
};

}  // namespace lightpath
