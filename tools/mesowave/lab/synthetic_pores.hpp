#pragma once
// Synthetic porosity images with a stated ground truth (`source = "synthetic"`
// lab data, docs/lab-raw-data.md), so mw-porosity can be tested on recovering it.
//
// Micro-CT stack: a block of mortar (cement paste with brighter sand grains)
// with air voids, voxelised slice by slice, surrounded by a margin of air as a
// scan of a specimen shows it (exclude it with a ROI). Pores are dark.
// Microscope face: a cut face of mortar whose voids were filled with white
// plaster (concrete paper, Section 3.1): pores are bright discs or irregular
// blobs on a textured gray matrix with a gentle illumination gradient.
//
// Pores are added one by one at random places (spheres/discs, or irregular
// clusters of 2-4 overlapping ones) until the pore fraction reaches the target;
// overlaps are unions, and near the target the radii shrink so that the last
// pore does not overshoot it by much. Each voxel (pixel) is split into 3x3x3 (4x4) subsamples
// and its pore coverage c in [0, 1] is the fraction of subsamples inside a
// pore; its gray level mixes pore and solid by c (partial volume), plus
// Gaussian noise. The TRUE porosity is sum(c) / (number of specimen voxels):
// exactly what was drawn, not the nominal target.
#include <array>
#include <cstdint>
#include <vector>

#include "mesowave/io/image.hpp"

namespace mesowave::lab {

enum class PoreShape { sphere, irregular };

struct SyntheticCtSpec {
  int specimen_px = 96;          ///< specimen width = height in each slice [voxels]
  int margin_px = 6;             ///< air around it
  int slices = 32;
  double voxel_um = 50;
  double porosity = 0.07;        ///< target pore volume fraction of the specimen
  double pore_radius_min_px = 1.5, pore_radius_max_px = 6.0;  ///< log-uniform radii
  PoreShape shape = PoreShape::sphere;
  double grain_fraction = 0.35;  ///< sand grains, volume fraction of the specimen (before voids)
  double grain_radius_min_px = 1.5, grain_radius_max_px = 3.0;
  double air_level = 9000, paste_level = 30000, grain_level = 36000;  ///< 16-bit gray levels
  double noise_sd = 1500;        ///< Gaussian noise [gray levels]
  std::uint64_t seed = 1;
};

struct SyntheticCtStack {
  std::vector<io::GrayImage> slices;       ///< 16 bit
  std::array<int, 4> specimen_roi{};       ///< x0, y0, width, height [px]
  double true_porosity = 0;                ///< over the whole specimen block
  std::vector<double> slice_porosity;      ///< per slice
  int pores = 0;                           ///< pores (clusters) drawn
};

SyntheticCtStack synthetic_ct_stack(const SyntheticCtSpec& spec);

struct SyntheticFaceSpec {
  int width_px = 256, height_px = 256;
  double pixel_um = 10;
  double porosity = 0.07;        ///< target pore area fraction
  double pore_radius_min_px = 2, pore_radius_max_px = 12;
  PoreShape shape = PoreShape::sphere;
  double grain_fraction = 0.4;   ///< area fraction of sand grains
  double grain_radius_min_px = 3, grain_radius_max_px = 10;
  double paste_level = 105, grain_level_min = 65, grain_level_max = 150;  ///< 8-bit gray
  double plaster_level = 228;    ///< pores filled with white plaster
  double illumination_gradient = 8;  ///< +- gray levels across the image
  double noise_sd = 5;
  std::uint64_t seed = 1;
};

struct SyntheticFace {
  io::GrayImage image;           ///< 8 bit
  double true_porosity = 0;      ///< sum of pore coverage / pixels
  int pores = 0;
};

SyntheticFace synthetic_face(const SyntheticFaceSpec& spec);

}  // namespace mesowave::lab
