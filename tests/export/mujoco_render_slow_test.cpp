// MuJoCo's offscreen renderer (OSMesa, software, no display) draws the exported Nao: with the
// visual geoms the robot stands out from the floor and sky in the middle of the picture, and
// without them (group 1 off) it is gone. Slow tier: llvmpipe renders a frame in about a second.

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "export_test_support.hpp"
#include "motoflex/export/exporter.hpp"
#include "motoflex/export/mujoco_render.hpp"

namespace motoflex {
namespace {

ExportedFile nao_mjcf(const RobotModel& model) {
  const ExportInput input{model, ParameterSet(model.parameters), model.default_servo, {}, 0.001};
  return find_exporter("mjcf")->write(input, {});
}

struct Difference {
  std::size_t pixels = 0;        // pixels whose colour changed by more than 30 of 255
  double centroid_x = 0.0;       // of those pixels, in image widths
  double centroid_y = 0.0;       // in image heights
  double width_fraction = 0.0;   // horizontal extent of those pixels, in image widths
  double height_fraction = 0.0;  // vertical extent, in image heights
};

Difference difference(const RgbImage& a, const RgbImage& b) {
  Difference out;
  int x_min = a.width_px, x_max = -1, y_min = a.height_px, y_max = -1;
  for (int y = 0; y < a.height_px; ++y) {
    for (int x = 0; x < a.width_px; ++x) {
      const std::size_t i = 3 * (static_cast<std::size_t>(y) * a.width_px + x);
      int change = 0;
      for (int c = 0; c < 3; ++c) change = std::max(change, std::abs(a.rgb[i + c] - b.rgb[i + c]));
      if (change <= 30) continue;
      ++out.pixels;
      out.centroid_x += x;
      out.centroid_y += y;
      x_min = std::min(x_min, x);
      x_max = std::max(x_max, x);
      y_min = std::min(y_min, y);
      y_max = std::max(y_max, y);
    }
  }
  if (out.pixels == 0) return out;
  out.centroid_x /= static_cast<double>(out.pixels) * a.width_px;
  out.centroid_y /= static_cast<double>(out.pixels) * a.height_px;
  out.width_fraction = static_cast<double>(x_max - x_min + 1) / a.width_px;
  out.height_fraction = static_cast<double>(y_max - y_min + 1) / a.height_px;
  return out;
}

TEST(MujocoRender, ExportedNaoIsVisibleInTheMiddleOfTheFrame) {
  const auto model = testing::load_robot("nao");
  const ExportedFile file = nao_mjcf(*model);
  MujocoRenderOptions options;
  options.width_px = 320;
  options.height_px = 240;
  const RgbImage robot = render_mjcf(file, options);
  options.visual_geoms = false;
  const RgbImage empty = render_mjcf(file, options);
  ASSERT_EQ(robot.rgb.size(), 320u * 240u * 3u);
  const Difference d = difference(robot, empty);
  std::printf("silhouette: %zu px (%.1f %%), centroid (%.2f, %.2f), extent %.2f x %.2f\n", d.pixels,
              100.0 * d.pixels / (320.0 * 240.0), d.centroid_x, d.centroid_y, d.width_fraction,
              d.height_fraction);
  // Measured: 7.6 % of the pixels, centroid (0.50, 0.48), extent 0.20 x 0.60.
  EXPECT_GT(d.pixels, 320u * 240u / 25u);  // > 4 % of the frame
  EXPECT_NEAR(d.centroid_x, 0.5, 0.15);
  EXPECT_NEAR(d.centroid_y, 0.5, 0.15);
  EXPECT_GT(d.height_fraction, 0.4);  // a standing robot: taller than wide
  EXPECT_GT(d.height_fraction, d.width_fraction);

  const auto png = testing::fresh_export_dir("render") / "nao.png";
  write_png(robot, png.string());
  std::ifstream in(png, std::ios::binary);
  char signature[8] = {};
  in.read(signature, 8);
  EXPECT_EQ(std::string(signature + 1, 3), "PNG");
  EXPECT_GT(std::filesystem::file_size(png), 1000u);
}

}  // namespace
}  // namespace motoflex
