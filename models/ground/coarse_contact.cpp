#include "models/ground/coarse_contact.h"

#include <algorithm>
#include <cstdint>

#include "models/ground/displacement.h"
#include "models/ground/erosion.h"
#include "models/ground/ground_model.h"
#include "models/ground/ground_params.h"
#include "models/ground/ground_state.h"

namespace repose {

namespace {

// Whole coarse cells [c0, c1] around fine cells [first, last] of an axis of n fine cells.
// In 64 bits: margin and factor come from the input (coarse_factor).
bool coarse_range(int first, int last, std::int64_t margin, int factor, int n, int* c0, int* c1) {
  *c0 = static_cast<int>(std::max<std::int64_t>(0, first - margin) / factor);
  *c1 = static_cast<int>(std::min<std::int64_t>(n / factor - 1, (last + margin) / factor));
  return *c1 >= *c0;
}

// Bilinear interpolation of the coarse change can take a fine cell below
// the base where its neighbours in the block stand higher. The block's
// volume is right (at least zero: the coarse height is), so its negative
// cells are lifted to zero and its positive ones scaled down by the same
// volume: the block keeps its volume, and no height goes below zero.
void keep_above_base(int i0, int j0, int f, HeightField* fine) {
  auto block = fine->heights().block(j0, i0, f, f);
  if (block.minCoeff() >= 0.0) return;
  const double total = std::max(0.0, block.sum());  // negative only by round-off
  const double positive = block.max(0.0).sum();
  block = block.max(0.0) * (positive > 0.0 ? total / positive : 0.0);
}

}  // namespace

CoarseContactResult deform_coarse(const GroundModel& model, const GroundParams& params, const FacesDown& faces_down,
                                  const Eigen::Vector3d& motion_m, UndersideRenderer& renderer, GroundState* state) {
  CoarseContactResult result;
  const Grid& g = model.grid;
  const int f = model.options.coarse_factor;
  const Footprint fp = footprint_of(faces_down.box, g);
  if (fp.empty()) return result;
  const std::int64_t margin = std::max(fp.ni, fp.nj) / 2 + 2 * static_cast<std::int64_t>(f);
  int ci0, ci1, cj0, cj1;
  if (!coarse_range(fp.i0, fp.i0 + fp.ni - 1, margin, f, g.nx, &ci0, &ci1) ||
      !coarse_range(fp.j0, fp.j0 + fp.nj - 1, margin, f, g.ny, &cj0, &cj1)) {
    return result;
  }
  Grid patch_grid = g;
  patch_grid.nx = ci1 - ci0 + 1;
  patch_grid.ny = cj1 - cj0 + 1;
  patch_grid.cell_size_m = g.cell_size_m * f;
  patch_grid.origin_x_m = g.origin_x_m + ci0 * f * g.cell_size_m;
  patch_grid.origin_y_m = g.origin_y_m + cj0 * f * g.cell_size_m;

  // restrict: average of the f x f fine cells; material of the first fine cell
  GroundModel patch = make_plain_ground_model(patch_grid, model.materials[0], model.options);
  patch.materials = model.materials;
  HeightField coarse(patch_grid, 0.0);
  const HeightField& fine = state->height;
  for (int J = 0; J < patch_grid.ny; ++J) {
    for (int I = 0; I < patch_grid.nx; ++I) {
      const int i0 = (ci0 + I) * f, j0 = (cj0 + J) * f;
      coarse.at(I, J) = fine.heights().block(j0, i0, f, f).mean();
      patch.material_index[static_cast<std::size_t>(patch.cell(I, J))] =
          static_cast<std::uint8_t>(model.material_at(model.cell(i0, j0)));
    }
  }
  const HeightField before = coarse;

  GroundState patch_state;
  patch_state.height = std::move(coarse);
  patch_state.erosion = ErosionMemory(patch_grid.cell_count(), 0);
  Ceiling ceiling;
  ceiling.undersides.push_back(find_underside_of_faces_down(faces_down, patch_state.height, renderer));
  const DisplacementResult d = displace(patch, params, ceiling.undersides[0], ceiling, motion_m, &patch_state);
  result.contact_cells = d.contact_cells;
  if (d.contact_cells == 0) return result;
  erode(patch, params, ceiling, &patch_state);
  state->ledger.compressed_m3 += patch_state.ledger.compressed_m3;
  state->ledger.left_grid_m3 += patch_state.ledger.left_grid_m3;
  state->ledger.bedrock_m3 = std::max(state->ledger.bedrock_m3, patch_state.ledger.bedrock_m3);

  // map back the change onto the fine cells of changed coarse cells
  HeightField change(patch_grid, patch_state.height.heights() - before.heights());
  for (int J = 0; J < patch_grid.ny; ++J) {
    for (int I = 0; I < patch_grid.nx; ++I) {
      const double dc = change.at(I, J);
      if (dc == 0.0) continue;
      const int i0 = (ci0 + I) * f, j0 = (cj0 + J) * f;
      double sum = 0.0;
      for (int j = j0; j < j0 + f; ++j) {
        for (int i = i0; i < i0 + f; ++i) {
          const double df = change.sample(g.centre_x(i), g.centre_y(j));
          state->height.at(i, j) += df;
          sum += df;
        }
      }
      const double correction = dc - sum / (static_cast<double>(f) * f);
      for (int j = j0; j < j0 + f; ++j) {
        for (int i = i0; i < i0 + f; ++i) {
          state->height.at(i, j) += correction;
          state->erosion.touch(model.cell(i, j));
          ++result.changed_fine_cells;
        }
      }
      keep_above_base(i0, j0, f, &state->height);
    }
  }
  return result;
}

}  // namespace repose
