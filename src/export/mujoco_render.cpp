#include "motoflex/export/mujoco_render.hpp"

#include <GL/osmesa.h>
#include <png.h>

#include <Eigen/Core>
#include <cmath>
#include <cstdio>
#include <memory>

#include "motoflex/core/error.hpp"
#include "mujoco_model.hpp"

namespace motoflex {
namespace {

// An OSMesa context drawing into `buffer`, current on this thread while it lives.
class OffscreenContext {
 public:
  OffscreenContext(int width_px, int height_px)
      : context_(OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, nullptr)),
        buffer_(static_cast<std::size_t>(width_px) * height_px * 4) {
    if (context_ == nullptr) throw ModelError("OSMesa cannot create a rendering context");
    if (!OSMesaMakeCurrent(context_, buffer_.data(), GL_UNSIGNED_BYTE, width_px, height_px)) {
      OSMesaDestroyContext(context_);
      throw ModelError("OSMesa cannot make its rendering context current");
    }
  }
  ~OffscreenContext() { OSMesaDestroyContext(context_); }
  OffscreenContext(const OffscreenContext&) = delete;
  OffscreenContext& operator=(const OffscreenContext&) = delete;

 private:
  OSMesaContext context_;
  std::vector<unsigned char> buffer_;
};

// MuJoCo's visualisation state for one model, freed in reverse order of creation.
struct SceneState {
  mjvScene scene;
  mjrContext context;
  SceneState(const mjModel* m) {
    mjv_defaultScene(&scene);
    mjr_defaultContext(&context);
    mjv_makeScene(m, &scene, 2000);
    mjr_makeContext(m, &context, mjFONTSCALE_100);
  }
  ~SceneState() {
    mjr_freeContext(&context);
    mjv_freeScene(&scene);
  }
  SceneState(const SceneState&) = delete;
  SceneState& operator=(const SceneState&) = delete;
};

// Points the free camera at the drawn geoms (planes left out: they are infinite): at the centre
// of their bounding box, far enough that the box's bounding sphere fills the vertical field of
// view `fill` times.
void frame_geoms(const mjModel& m, const mjData& d, const mjvOption& option, double fill,
                 mjvCamera& camera) {
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(1e9), hi = Eigen::Vector3d::Constant(-1e9);
  for (int g = 0; g < m.ngeom; ++g) {
    const int group = m.geom_group[g];
    if (m.geom_type[g] == mjGEOM_PLANE || group < 0 || group >= mjNGROUP ||
        !option.geomgroup[group]) {
      continue;
    }
    const Eigen::Vector3d p(d.geom_xpos[3 * g], d.geom_xpos[3 * g + 1], d.geom_xpos[3 * g + 2]);
    lo = lo.cwiseMin(p - Eigen::Vector3d::Constant(m.geom_rbound[g]));
    hi = hi.cwiseMax(p + Eigen::Vector3d::Constant(m.geom_rbound[g]));
  }
  if (lo.x() > hi.x()) {  // nothing drawn: MuJoCo's own statistic
    for (int k = 0; k < 3; ++k) camera.lookat[k] = m.stat.center[k];
    camera.distance = 1.5 * m.stat.extent;
    return;
  }
  const Eigen::Vector3d centre = 0.5 * (lo + hi);
  const double radius = 0.5 * (hi - lo).norm();
  for (int k = 0; k < 3; ++k) camera.lookat[k] = centre[k];
  const double half_fov_rad = 0.5 * m.vis.global.fovy * M_PI / 180.0;
  camera.distance = radius / (fill * std::tan(half_fov_rad));
}

}  // namespace

RgbImage render_mjcf(const ExportedFile& mjcf, const MujocoRenderOptions& options) {
  std::string error;
  const detail::MjModelPtr m = detail::load_mjcf_text(mjcf.text, mjcf.assets, error);
  if (!m) throw ModelError("MuJoCo cannot load the exported model: " + error);
  const detail::MjDataPtr d(mj_makeData(m.get()));
  mj_forward(m.get(), d.get());

  const int width = options.width_px;
  const int height = options.height_px;
  m->vis.global.offwidth = width;
  m->vis.global.offheight = height;
  // The export has no lights: a brighter headlight than MuJoCo's default (ambient 0.1,
  // diffuse 0.4) shows the shapes.
  for (int k = 0; k < 3; ++k) {
    m->vis.headlight.ambient[k] = 0.35f;
    m->vis.headlight.diffuse[k] = 0.65f;
  }
  OffscreenContext gl(width, height);
  SceneState state(m.get());
  mjr_setBuffer(mjFB_OFFSCREEN, &state.context);
  if (state.context.currentBuffer != mjFB_OFFSCREEN) {
    throw ModelError("MuJoCo's offscreen framebuffer is not available under OSMesa");
  }

  mjvOption option;
  mjv_defaultOption(&option);
  option.geomgroup[1] = options.visual_geoms ? 1 : 0;
  option.geomgroup[3] = 0;
  mjvCamera camera;
  mjv_defaultCamera(&camera);
  camera.type = mjCAMERA_FREE;
  camera.azimuth = options.azimuth_deg;
  camera.elevation = options.elevation_deg;
  // Framed on the robot with its visuals on, so that both renders share one camera.
  mjvOption framing = option;
  framing.geomgroup[1] = 1;
  frame_geoms(*m, *d, framing, options.fill, camera);
  mjv_updateScene(m.get(), d.get(), &option, nullptr, &camera, mjCAT_ALL, &state.scene);
  const mjrRect viewport = {0, 0, width, height};
  mjr_render(viewport, &state.scene, &state.context);

  RgbImage image;
  image.width_px = width;
  image.height_px = height;
  std::vector<std::uint8_t> bottom_up(static_cast<std::size_t>(width) * height * 3);
  mjr_readPixels(bottom_up.data(), nullptr, viewport, &state.context);
  image.rgb.resize(bottom_up.size());
  const std::size_t row = static_cast<std::size_t>(width) * 3;
  for (int y = 0; y < height; ++y) {
    std::copy_n(bottom_up.begin() + (height - 1 - y) * row, row, image.rgb.begin() + y * row);
  }
  return image;
}

void write_png(const RgbImage& image, const std::string& path) {
  std::unique_ptr<FILE, int (*)(FILE*)> file(std::fopen(path.c_str(), "wb"), &std::fclose);
  if (!file) throw InputError(path, 0, "png", "cannot open the file for writing");
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png != nullptr ? png_create_info_struct(png) : nullptr;
  if (png == nullptr || info == nullptr || setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    throw InputError(path, 0, "png", "libpng failed to write the image");
  }
  png_init_io(png, file.get());
  png_set_IHDR(png, info, static_cast<png_uint_32>(image.width_px),
               static_cast<png_uint_32>(image.height_px), 8, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_write_info(png, info);
  const std::size_t row = static_cast<std::size_t>(image.width_px) * 3;
  for (int y = 0; y < image.height_px; ++y) {
    png_write_row(png, const_cast<png_bytep>(image.rgb.data() + y * row));
  }
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
}

}  // namespace motoflex
