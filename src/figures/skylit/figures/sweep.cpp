// Parameter sweeps (sweep.h): `--vary` parsing, the Cartesian product in row-major
// order, labels and cell file names.
#include "skylit/figures/sweep.h"

#include <set>

#include "skylit/core/error.h"

namespace skylit {

namespace {

std::string trimmed(const std::string& s) {
  const size_t first = s.find_first_not_of(" \t");
  if (first == std::string::npos) return {};
  return s.substr(first, s.find_last_not_of(" \t") - first + 1);
}

std::string assignment_label(const SweepParameter& parameter, const std::string& value) {
  return parameter.path + " = " + value;
}

}  // namespace

SweepParameter parse_sweep_parameter(const std::string& argument) {
  const auto fail = [&](const std::string& why) { throw InputError("--vary " + argument + ": " + why); };
  const size_t equals = argument.find('=');
  if (equals == std::string::npos) fail("expected PATH=V1,V2,..., e.g. sun.altitude_deg=17,60,4");
  SweepParameter parameter{trimmed(argument.substr(0, equals)), {}};
  if (parameter.path.empty()) fail("no path before '='");
  const std::string list = argument.substr(equals + 1);
  if (trimmed(list).empty()) fail("no values after '='");
  const char separator = list.find(';') != std::string::npos ? ';' : ',';
  size_t start = 0;
  while (true) {
    const size_t end = list.find(separator, start);
    const std::string value = trimmed(list.substr(start, end - start));
    if (value.empty())
      fail("an empty value; values are separated by ',' (or by ';' when they hold commas, e.g. [0,1,2];[3,4,5])");
    parameter.values.push_back(value);
    if (end == std::string::npos) break;
    start = end + 1;
  }
  return parameter;
}

SweepPlan plan_sweep(std::vector<SweepParameter> parameters) {
  if (parameters.empty()) throw InputError("a sweep needs at least one --vary PATH=V1,V2,...");
  std::set<std::string> paths;
  for (const SweepParameter& p : parameters)
    if (!paths.insert(p.path).second) throw InputError("--vary " + p.path + " is given twice");

  SweepPlan plan;
  plan.parameters = std::move(parameters);
  const auto& ps = plan.parameters;
  const SweepParameter& last = ps.back();
  plan.columns = last.values.size();
  for (const std::string& v : last.values) plan.column_labels.push_back(assignment_label(last, v));

  // The row parameters' combinations, the first parameter varying slowest.
  std::vector<std::vector<std::string>> row_values = {{}};
  for (size_t p = 0; p + 1 < ps.size(); ++p) {
    std::vector<std::vector<std::string>> next;
    for (const auto& prefix : row_values)
      for (const std::string& v : ps[p].values) {
        next.push_back(prefix);
        next.back().push_back(v);
      }
    row_values = std::move(next);
  }
  plan.rows = row_values.size();
  for (size_t r = 0; r < plan.rows && ps.size() > 1; ++r) {
    std::string label;
    for (size_t p = 0; p < row_values[r].size(); ++p)
      label += (p > 0 ? " / " : "") + assignment_label(ps[p], row_values[r][p]);
    plan.row_labels.push_back(label);
  }
  for (size_t r = 0; r < plan.rows; ++r)
    for (size_t c = 0; c < plan.columns; ++c) {
      SweepCombination combination{plan.combinations.size(), r, c, row_values[r]};
      combination.values.push_back(last.values[c]);
      plan.combinations.push_back(std::move(combination));
    }
  return plan;
}

std::vector<std::string> sweep_overrides(const SweepPlan& plan, const SweepCombination& combination) {
  std::vector<std::string> overrides;
  for (size_t p = 0; p < plan.parameters.size(); ++p)
    overrides.push_back(plan.parameters[p].path + "=" + combination.values.at(p));
  return overrides;
}

std::string combination_label(const SweepPlan& plan, const SweepCombination& combination) {
  std::string label;
  for (size_t p = 0; p < plan.parameters.size(); ++p)
    label += (p > 0 ? ", " : "") + assignment_label(plan.parameters[p], combination.values.at(p));
  return label;
}

std::string file_name_part(const std::string& value) {
  constexpr size_t kMaxLength = 32;
  std::string part;
  for (const char c : value) {
    const bool kept =
        (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '.' || c == '+' || c == '-';
    if (kept)
      part += c;
    else if (!part.empty() && part.back() != '_')
      part += '_';
  }
  if (part.size() > kMaxLength) part.resize(kMaxLength);
  while (!part.empty() && part.back() == '_') part.pop_back();
  return part.empty() ? "v" : part;
}

std::filesystem::path sweep_cell_path(const std::filesystem::path& sheet, const SweepPlan& plan,
                                      const SweepCombination& combination, const std::string& extension) {
  const std::string count = std::to_string(plan.combinations.size());
  std::string number = std::to_string(combination.index + 1);
  number.insert(0, count.size() > number.size() ? count.size() - number.size() : 0, '0');
  std::string name = sheet.stem().string() + "_" + number;
  for (const std::string& value : combination.values) {
    name += '_';
    name += file_name_part(value);
  }
  return sheet.parent_path() / (name + extension);
}

}  // namespace skylit
