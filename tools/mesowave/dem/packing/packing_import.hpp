#pragma once
// Packings made elsewhere, and ours for other codes, so two codes can be
// compared on the very same spheres.
//
// CSV (io/csv.hpp rules: one header row, '#' comments): columns x, y, z and r
// (or d, the diameter), each with its unit in the name - x_m, x_mm or x_um,
// all four in any of the units - and an optional integer `id` column. Other
// columns are ignored.
//
// Yade text (yade.export.textExt / yade.ymport.textExt): whitespace-separated
// "x y z r" per line in metres; '#' starts a comment line; a "#format NAME"
// line selects the layout: x_y_z_r (default), x_y_z_r_matId (a fifth column,
// ignored) or id_x_y_z_r_matId (Yade ignores the id; so do we).
#include <filesystem>
#include <string>

#include "mesowave/dem/packing/packing.hpp"

namespace mesowave::dem {

/// InputError (file and line) for missing columns, a non-number, a radius
/// that is not positive, duplicate ids, or no sphere at all. Ids default to
/// 0..n-1. The container is left empty (shape "box", zero corners): the
/// caller sets it (see bounding_box in packing_stats.hpp).
Packing read_packing_csv(const std::filesystem::path& path);
Packing parse_packing_csv(const std::string& text, const std::string& origin);

Packing read_yade_text(const std::filesystem::path& path);
Packing parse_yade_text(const std::string& text, const std::string& origin);

/// Yade's textExt layout ("#format x_y_z_r", then "x y z r" in metres), with
/// every number written so that it reads back as the same double. `comment`
/// lines are written after the format line, each prefixed with '#'.
std::string yade_text(const Packing& packing, const std::string& comment = "");
/// CSV with id, x_m, y_m, z_m, r_m (numbers that read back exactly).
std::string packing_csv(const Packing& packing);

}  // namespace mesowave::dem
