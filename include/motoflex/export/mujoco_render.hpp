#pragma once

// One frame of an MJCF export drawn by MuJoCo's own renderer, offscreen (OSMesa: no display,
// no GPU), for pictures of the exported robot and tests that it is visible.

#include <cstdint>
#include <string>
#include <vector>

#include "motoflex/export/exported_file.hpp"

namespace motoflex {

struct MujocoRenderOptions {
  int width_px = 640;
  int height_px = 480;
  double azimuth_deg = 135.0;    // camera around the vertical axis (MuJoCo's free camera)
  double elevation_deg = -15.0;  // negative: looking down
  double fill = 0.8;             // the robot's bounding sphere fills this much of the height
  bool visual_geoms = true;      // draw geom group 1 (the export's visual geoms)
};

// An RGB image, rows top to bottom.
struct RgbImage {
  int width_px = 0;
  int height_px = 0;
  std::vector<std::uint8_t> rgb;  // 3 bytes per pixel
};

// Loads the MJCF (with its meshes) into MuJoCo, runs mj_forward in the model's initial pose and
// renders it with the free camera looking at the centre of the drawn geoms' bounding box (planes
// left out) from far enough to see all of them, a brightened headlight, geom groups 0 and 2 always
// drawn, group 1 as options.visual_geoms says and group 3 (collision geoms) hidden. Throws
// ModelError when MuJoCo rejects the model or no OSMesa context can be made.
RgbImage render_mjcf(const ExportedFile& mjcf, const MujocoRenderOptions& options = {});

// Writes `image` as an 8-bit RGB PNG (libpng). Throws InputError when the file cannot be written.
void write_png(const RgbImage& image, const std::string& path);

}  // namespace motoflex
