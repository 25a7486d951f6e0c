#include "models/tearing/tear_path.h"

#include <algorithm>
#include <cmath>

namespace repose {

namespace {

// Labels the 8-connected components of torn cells; returns the label per
// cell (-1 intact) and the number of components.
int label_components(const SheetModel& model, const SheetState& state, std::vector<int>* label) {
  label->assign(static_cast<std::size_t>(model.cell_count()), -1);
  int components = 0;
  std::vector<int> stack;
  for (int seed = 0; seed < model.cell_count(); ++seed) {
    if (state.intact(seed) || (*label)[seed] >= 0) continue;
    (*label)[seed] = components;
    stack.push_back(seed);
    while (!stack.empty()) {
      const int c = stack.back();
      stack.pop_back();
      const int i = c % model.cells_x, j = c / model.cells_x;
      for (int dj = -1; dj <= 1; ++dj) {
        for (int di = -1; di <= 1; ++di) {
          const int ni = i + di, nj = j + dj;
          if (ni < 0 || nj < 0 || ni >= model.cells_x || nj >= model.cells_y) continue;
          const int n = model.cell(ni, nj);
          if (state.intact(n) || (*label)[n] >= 0) continue;
          (*label)[n] = components;
          stack.push_back(n);
        }
      }
    }
    ++components;
  }
  return components;
}

// The largest component; on a tie the notch's, else the lowest label (labels
// follow the lowest cell index of each component).
int tear_component(const SheetModel& model, const std::vector<int>& label, int components) {
  std::vector<int> size(components, 0);
  for (const int l : label) {
    if (l >= 0) ++size[l];
  }
  const int largest = *std::max_element(size.begin(), size.end());
  if (!model.notch_cells.empty() && size[label[model.notch_cells.front()]] == largest) {
    return label[model.notch_cells.front()];
  }
  return static_cast<int>(std::find(size.begin(), size.end(), largest) - size.begin());
}

void fill_shape_measures(TearPath* path) {
  const auto& p = path->points;
  const int n = static_cast<int>(p.size());
  for (int k = 1; k < n; ++k) path->path_length_m += (p[k] - p[k - 1]).norm();
  const double chord = n > 1 ? (p.back() - p.front()).norm() : 0.0;
  path->tortuosity = chord > 0.0 ? path->path_length_m / chord : 1.0;
  double sy = 0, sx = 0, syy = 0, sxy = 0, deviation2 = 0;
  for (const auto& q : p) {
    sy += q.y();
    sx += q.x();
    syy += q.y() * q.y();
    sxy += q.x() * q.y();
    deviation2 += (q.x() - p.front().x()) * (q.x() - p.front().x());
  }
  path->deviation_m = std::sqrt(deviation2 / n);
  const double det = n * syy - sy * sy;
  const double b = det > 0.0 ? (n * sxy - sy * sx) / det : 0.0, a = (sx - b * sy) / n;
  double residual2 = 0.0;
  for (const auto& q : p) residual2 += (q.x() - a - b * q.y()) * (q.x() - a - b * q.y());
  path->roughness_m = std::sqrt(residual2 / n);
}

}  // namespace

TearPath measure_tear_path(const SheetModel& model, const SheetState& state) {
  TearPath path;
  std::vector<int> label;
  const int components = label_components(model, state, &label);
  if (components == 0) return path;
  const int tear = tear_component(model, label, components);
  path.holds_notch = !model.notch_cells.empty() && label[model.notch_cells.front()] == tear;
  const double h = model.cell_size_m;
  for (int j = model.cells_y - 1; j >= 0; --j) {
    double sum_x = 0.0;
    int count = 0;
    for (int i = 0; i < model.cells_x; ++i) {
      const int l = label[model.cell(i, j)];
      if (l == tear) {
        sum_x += (i + 0.5) * h;
        ++count;
      }
    }
    path.tear_cells += count;
    if (count > 0) path.points.emplace_back(sum_x / count, (j + 0.5) * h);
  }
  for (const int l : label) path.stray_cells += (l >= 0 && l != tear);
  int lowest_row = model.cells_y;
  for (int c = 0; c < model.cell_count(); ++c) {
    if (label[c] == tear) lowest_row = std::min(lowest_row, c / model.cells_x);
  }
  path.depth_m = (model.cells_y - lowest_row) * h;
  fill_shape_measures(&path);
  return path;
}

}  // namespace repose
