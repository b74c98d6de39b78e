// Parameter sweeps (`skylit sweep`, docs/sweeps.md): `--vary PATH=V1,V2,...` arguments
// become every combination of their values (the Cartesian product), laid out as the
// rows and columns of a contact sheet, with the labels that name them, the `--set`
// overrides that make each one's scene, and the file each cell image is written to.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace skylit {

// One `--vary`: a scene path (as for `--set`) and its values as the user wrote them
// (each read like a `--set` value when applied: JSON if it parses, else a string).
struct SweepParameter {
  std::string path;
  std::vector<std::string> values;
};

// Reads `PATH=V1,V2,...`. The values are split on ';' if the list holds one (for values
// with commas inside, such as `[0,-40,2];[0,-60,2]`), else on ','; spaces around each
// are dropped. InputError "--vary <argument>: ..." without '=', a path or a value, or
// with an empty value.
SweepParameter parse_sweep_parameter(const std::string& argument);

// One combination of values, one per parameter, in the parameters' order.
struct SweepCombination {
  std::size_t index = 0;  // 0-based, row-major (rows first, then columns)
  std::size_t row = 0, column = 0;
  std::vector<std::string> values;
};

// Every combination and the sheet's layout. The last parameter gives the columns and
// the ones before it the rows (the first varying slowest); one parameter gives a
// single row. Row labels join "path = value" of each row parameter with " / ".
struct SweepPlan {
  std::vector<SweepParameter> parameters;
  std::size_t rows = 0, columns = 0;
  std::vector<std::string> row_labels;     // empty with a single parameter
  std::vector<std::string> column_labels;  // "materials.walls = tile"
  std::vector<SweepCombination> combinations;
};

// InputError if there is no parameter or a path is given twice.
SweepPlan plan_sweep(std::vector<SweepParameter> parameters);

// The `--set` assignments ("path=value") that make a combination's scene.
std::vector<std::string> sweep_overrides(const SweepPlan& plan, const SweepCombination& combination);

// "sun.altitude_deg = 17, materials.walls = tile", for messages and progress lines.
std::string combination_label(const SweepPlan& plan, const SweepCombination& combination);

// A value as part of a file name: ASCII letters, digits, '.', '+' and '-' kept, runs
// of anything else as one '_', none at the ends, at most 32 characters; "v" if nothing
// is left.
std::string file_name_part(const std::string& value);

// Where a combination's image goes, next to the sheet: for `dir/fig7.png` and the
// extension ".png", `dir/fig7_<n>_<values>.png`, n counting from 1 and zero-padded to
// the width of the number of combinations, the values' file_name_part joined by '_'.
std::filesystem::path sweep_cell_path(const std::filesystem::path& sheet, const SweepPlan& plan,
                                      const SweepCombination& combination, const std::string& extension);

}  // namespace skylit
