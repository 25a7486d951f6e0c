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

// The patch of whole coarse cells [ci0, ci1] x [cj0, cj1] restricted from
// the fine field: each coarse cell the average of its f x f fine cells (so
// the patch holds the fine field's volume), its material the first fine cell's.
struct CoarsePatch {
  int ci0 = 0, cj0 = 0;
  GroundModel model;
  HeightField height;
};

CoarsePatch restrict_patch(const GroundModel& model, const HeightField& fine, int ci0, int ci1, int cj0, int cj1) {
  const Grid& g = model.grid;
  const int f = model.options.coarse_factor;
  Grid patch_grid = g;
  patch_grid.nx = ci1 - ci0 + 1;
  patch_grid.ny = cj1 - cj0 + 1;
  patch_grid.cell_size_m = g.cell_size_m * f;
  patch_grid.origin_x_m = g.origin_x_m + ci0 * f * g.cell_size_m;
  patch_grid.origin_y_m = g.origin_y_m + cj0 * f * g.cell_size_m;
  CoarsePatch patch{ci0, cj0, make_plain_ground_model(patch_grid, model.materials[0], model.options),
                    HeightField(patch_grid, 0.0)};
  patch.model.materials = model.materials;
  for (int J = 0; J < patch_grid.ny; ++J) {
    for (int I = 0; I < patch_grid.nx; ++I) {
      const int i0 = (ci0 + I) * f, j0 = (cj0 + J) * f;
      patch.height.at(I, J) = fine.heights().block(j0, i0, f, f).mean();
      patch.model.material_index[static_cast<std::size_t>(patch.model.cell(I, J))] =
          static_cast<std::uint8_t>(model.material_at(model.cell(i0, j0)));
    }
  }
  return patch;
}

// Maps each changed coarse cell's change back onto its fine cells: bilinear
// interpolation of the change, then an equal share of what the interpolation
// missed, so the block's volume change is the coarse cell's exactly; the
// changed fine cells join the fine erosion memory. Returns their count.
int prolong_change(const GroundModel& model, const CoarsePatch& patch, const HeightField& change, GroundState* state) {
  const Grid& g = model.grid;
  const int f = model.options.coarse_factor;
  int changed_fine_cells = 0;
  for (int J = 0; J < change.grid().ny; ++J) {
    for (int I = 0; I < change.grid().nx; ++I) {
      const double dc = change.at(I, J);
      if (dc == 0.0) continue;
      const int i0 = (patch.ci0 + I) * f, j0 = (patch.cj0 + J) * f;
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
          ++changed_fine_cells;
        }
      }
      keep_above_base(i0, j0, f, &state->height);
    }
  }
  return changed_fine_cells;
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
  CoarsePatch patch = restrict_patch(model, state->height, ci0, ci1, cj0, cj1);
  const HeightField before = patch.height;

  GroundState patch_state;
  patch_state.height = std::move(patch.height);
  patch_state.erosion = ErosionMemory(before.grid().cell_count(), 0);
  Ceiling ceiling;
  ceiling.undersides.push_back(find_underside_of_faces_down(faces_down, patch_state.height, renderer));
  const DisplacementResult d = displace(patch.model, params, ceiling.undersides[0], ceiling, motion_m, &patch_state);
  result.contact_cells = d.contact_cells;
  if (d.contact_cells == 0) return result;
  erode(patch.model, params, ceiling, &patch_state);
  state->ledger.compressed_m3 += patch_state.ledger.compressed_m3;
  state->ledger.left_grid_m3 += patch_state.ledger.left_grid_m3;
  state->ledger.bedrock_m3 = std::max(state->ledger.bedrock_m3, patch_state.ledger.bedrock_m3);

  const HeightField change(before.grid(), patch_state.height.heights() - before.heights());
  result.changed_fine_cells = prolong_change(model, patch, change, state);
  return result;
}

}  // namespace repose
