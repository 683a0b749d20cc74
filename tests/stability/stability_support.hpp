// Shared helpers of the stability suite: rendering a SceneDesc, measuring images with numbers
// (pixel-difference fractions, background counts, speckles, NaN), and recording each case's
// figures and image for scripts/stability-report.
#pragma once

#include <string>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "render/renderer.hpp"
#include "render/scene/scene.hpp"

namespace rts::stability {

using render::Color;
using render::Mat4;
using render::SceneDesc;
using render::Vec3;

// Renders with the given thread count (and AOVs, to check them for NaN too).
render::RenderResult render_scene(const SceneDesc& s, int threads = 2, bool aovs = false);

// 8-bit sRGB codes of a linear image (clamped), 3 per pixel.
std::vector<uint8_t> to_srgb8(const render::Image& img);

// Fraction of pixels where any channel differs by more than `threshold` codes (of 255).
double differing_fraction(const render::Image& a, const render::Image& b, int threshold = 8);
// Pixels exactly equal to the given linear color (e.g. the background).
int count_color(const render::Image& img, const Color& c);
// Pixels whose value is NaN or infinite in any channel.
int count_non_finite(const render::Image& img);
// Isolated outliers: pixels differing by more than `threshold` codes from all 4 neighbours
// that agree among themselves (within threshold), the signature of acne and z-fighting.
int count_speckles(const render::Image& img, int threshold = 24);
// Pixels whose every channel is below 1/255 after encoding.
int count_black(const render::Image& img);

// One figure of one case, appended to RTS_STABILITY_OUT/figures.tsv:
// group, case, metric, value, limit (what the suite requires), image file ("" for none).
void record(const std::string& group, const std::string& name, const std::string& metric, double value,
            const std::string& limit, const std::string& image = "");
// Writes the image to RTS_STABILITY_OUT/<file>.png and returns the file name.
std::string save(const render::Image& img, const std::string& file);

// Building blocks.
render::MaterialId add_material(SceneDesc& s, const render::MaterialDesc& m);
render::NodeId add_shape(SceneDesc& s, render::ShapeGeometry g, render::MaterialId m = render::kNoId);
render::NodeId add_light(SceneDesc& s, const render::LightDesc& l);
render::NodeId add_group(SceneDesc& s, std::vector<render::Child> children);
// A CSG block of `children` (its material `m` for children without their own).
render::NodeId add_csg(SceneDesc& s, render::CsgOp op, std::vector<render::Child> children,
                       render::MaterialId m = render::kNoId);
void place(SceneDesc& s, render::NodeId node, const Mat4& transform = Mat4(1.0));
render::MaterialDesc matte(Color c);
render::MaterialDesc emissive(Color c);
// A UV sphere of `rings` x `segments` quads (2 triangles each, closed at the poles).
std::shared_ptr<render::MeshData> uv_sphere_mesh(Vec3 center, double radius, int rings, int segments);
// A cube [-h,h]^3, each face an n x n grid of quads (vertices shared along edges and corners).
std::shared_ptr<render::MeshData> grid_cube_mesh(double h, int n);
// A flat grid in the z = 0 plane, [-h,h]^2, n x n quads.
std::shared_ptr<render::MeshData> grid_mesh(double h, int n);
// Adds a mesh to the scene and returns its shape node.
render::NodeId add_mesh(SceneDesc& s, std::shared_ptr<render::MeshData> mesh, render::MaterialId m,
                        bool smooth = false);

inline Mat4 translate(Vec3 v) { return glm::translate(Mat4(1.0), v); }
inline Mat4 scale(double k) { return glm::scale(Mat4(1.0), Vec3(k)); }
inline Mat4 rotate_deg(double deg, Vec3 axis) { return glm::rotate(Mat4(1.0), glm::radians(deg), axis); }

}  // namespace rts::stability
