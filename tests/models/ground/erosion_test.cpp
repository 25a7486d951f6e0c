// Erosion: settling to the angle of repose, locality, the memory, stability in sigma.
#include "models/ground/erosion.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>
#include <vector>
#include <random>

#include "models/core/base/error.h"
#include "tests/models/ground/ground_fixtures.h"

namespace repose {
namespace {

using namespace repose::testing;

// A column of material on a flat ground, all cells remembered.
GroundState column(const GroundModel& model, double base_m, double peak_m, int half_width) {
  GroundState state = make_ground_state(model, HeightField(model.grid, base_m));
  const int ci = model.grid.nx / 2, cj = model.grid.ny / 2;
  for (int j = cj - half_width; j < cj + half_width; ++j) {
    for (int i = ci - half_width; i < ci + half_width; ++i) {
      state.height.at(i, j) = peak_m;
      state.erosion.touch(model.cell(i, j));
    }
  }
  state.ledger.initial_m3 = state.height.volume_m3();
  return state;
}

void settle(const GroundModel& model, const GroundParams& params, GroundState* state, int max_steps) {
  for (int s = 0; s < max_steps && !state->erosion.empty(); ++s) {
    erode(model, params, Ceiling{}, state);
    state->erosion.end_step();
  }
}

TEST(Erosion, TwoCellsSettleExactlyAtTheAngleOfRepose) {
  Material m = sand();
  m.sigma = 0.25;
  const GroundModel model = make_plain_ground_model(centred_grid(2, 1, 0.01), m);
  GroundState state = make_ground_state(model, HeightField(model.grid, 0.0));
  state.height.at(0, 0) = 0.1;
  state.erosion.touch(0);
  settle(model, GroundParams{{m}}, &state, 1000);
  // analytic: the pair ends at dh = h tan(theta) and keeps its volume
  EXPECT_NEAR(state.height.at(0, 0) - state.height.at(1, 0), 0.01 * std::tan(m.repose_angle_rad),
              kErosionToleranceFraction * 0.01 * 1.01);
  EXPECT_NEAR(state.height.at(0, 0) + state.height.at(1, 0), 0.1, 1e-15);
  EXPECT_TRUE(state.erosion.empty());
}

TEST(Erosion, SettledSlopesDoNotExceedTheAngleOfRepose) {
  for (const double theta_deg : {0.1, 10.0, 30.0, 60.0, 89.0}) {
    for (const double sigma : {0.03, 0.1, 0.2, 0.25}) {
      Material m = sand();
      m.repose_angle_rad = theta_deg * kDeg;
      m.sigma = sigma;
      GroundModelSpec options;
      options.erosion_memory_steps = 5;
      const GroundModel model = make_plain_ground_model(centred_grid(40, 40, 0.01), m, options);
      GroundState state = column(model, 0.02, 0.1, 3);
      settle(model, GroundParams{{m}}, &state, 200000);
      ASSERT_TRUE(state.erosion.empty()) << theta_deg << " " << sigma;
      // stated tolerance: tan(theta) + kErosionToleranceFraction
      EXPECT_LE(max_slope(state.height), std::tan(m.repose_angle_rad) + kErosionToleranceFraction * 1.01)
          << theta_deg << " deg, sigma " << sigma;
      EXPECT_NEAR(state.height.volume_m3(), state.ledger.initial_m3, 1e-14);
      EXPECT_TRUE(state.height.all_finite());
    }
  }
}

TEST(Erosion, NinetyDegreesNeverErodes) {
  Material m = sand();
  m.repose_angle_rad = 90 * kDeg;
  const GroundModel model = make_plain_ground_model(centred_grid(16, 16, 0.01), m);
  GroundState state = column(model, 0.0, 1.0, 2);
  const ArrayXXdR before = state.height.heights();
  settle(model, GroundParams{{m}}, &state, 10);
  EXPECT_TRUE((state.height.heights() == before).all());
}

TEST(Erosion, CostFollowsTheActiveRegion) {
  const Material m = sand();
  const GroundModel model = make_plain_ground_model(centred_grid(512, 512, 0.01), m);
  GroundState state = column(model, 0.0, 0.05, 2);
  const ErosionResult r = erode(model, GroundParams{{m}}, Ceiling{}, &state);
  // En = 5 passes, each ring grows by one cell: far fewer pairs than the grid's 2 * 512^2
  EXPECT_GT(r.moves, 0);
  EXPECT_LT(r.pair_visits, 5 * 4 * 20 * 20);
  EXPECT_EQ(state.height.at(0, 0), 0.0);
}

// The volume (m^3) one step's erosion carries out of a 6 cm square column 5 cm high.
double one_step_outflow_m3(double cell_m, int erosion_iterations, double erosion_iterations_cell_m) {
  Material m = sand();
  m.erosion_iterations = erosion_iterations;
  m.erosion_iterations_cell_m = erosion_iterations_cell_m;
  const int cells = static_cast<int>(std::lround(0.4 / cell_m)), half = static_cast<int>(std::lround(0.03 / cell_m));
  const GroundModel model = make_plain_ground_model(centred_grid(cells, cells, cell_m), m);
  GroundState state = column(model, 0.0, 0.05, half);
  const double before = state.height.volume_m3();
  erode(model, GroundParams{{m}}, Ceiling{}, &state);
  const int first = cells / 2 - half;  // the column's cells are rows and columns [first, first + 2 half)
  return before - state.height.heights().block(first, first, 2 * half, 2 * half).sum() * model.grid.cell_area_m2();
}

// A pass moves sigma times a pair's excess across the face between two cells,
// a diffusion of about sigma h^2 per pass: with En given at a cell size (passes
// scaled with the cells' area) a step sheds about the same volume on any grid;
// as a count of passes (the paper's En) finer cells shed less, and passes
// scaled with the cell size alone are not enough.
TEST(Erosion, PassesGivenAtACellSizeMoveAlikePerStepOnAnyGrid) {
  const double coarse = one_step_outflow_m3(0.01, 4, 0.0);
  EXPECT_NEAR(one_step_outflow_m3(0.005, 4, 0.01) / coarse, 1.0, 0.05);   // 16 passes
  EXPECT_NEAR(one_step_outflow_m3(0.0025, 4, 0.01) / coarse, 1.0, 0.05);  // 64 passes
  EXPECT_LT(one_step_outflow_m3(0.005, 4, 0.0) / coarse, 0.6);            // 4 passes
  EXPECT_LT(one_step_outflow_m3(0.005, 8, 0.0) / coarse, 0.8);            // 8: scaled with the cell size
}

TEST(Erosion, NeverRisesAboveTheCeiling) {
  const Material m = sand();
  const GroundModel model = make_plain_ground_model(centred_grid(16, 16, 0.01), m);
  GroundState state = column(model, 0.0, 0.1, 2);
  // a flat plate 1 cm above the ground over the right half
  Ceiling ceiling;
  Underside plate;
  plate.footprint = Footprint{8, 0, 8, 16};
  plate.z_m = ArrayXXdR::Constant(16, 8, 0.01);
  ceiling.undersides.push_back(plate);
  for (int s = 0; s < 50; ++s) erode(model, GroundParams{{m}}, ceiling, &state);
  for (int j = 0; j < 16; ++j) {
    for (int i = 10; i < 16; ++i) EXPECT_LE(state.height.at(i, j), 0.01 + 1e-15);
  }
  EXPECT_NEAR(state.height.volume_m3(), state.ledger.initial_m3, 1e-15);
}

// A call's passes are full sweeps of the remembered cells, each from the
// heights the last one left: a call of En passes equals En calls of one pass
// each, on random bumpy grounds, most cells remembered (the rest joins as it
// is reached), under a random plate. Bit for bit. (A pass restricted to the
// cells next to the last pass's fluxes must pass it too: issue 12 tried one,
// measured it dearer than the sweep, and withdrew it.)
TEST(Erosion, PassesAfterTheFirstFindWhatFullSweepsFind) {
  for (const unsigned seed : {1u, 2u, 3u, 4u}) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    Material m = sand();
    m.sigma = 0.1 + 0.15 * u(rng);
    const GroundModel model = make_plain_ground_model(centred_grid(40, 30, 0.01), m);
    GroundState start = make_ground_state(model, HeightField(model.grid, 0.0));
    // a level bed with a few bumps, most cells remembered: the passes after
    // the first find few fluxes among many cells, so they restrict
    for (int j = 0; j < 30; ++j) {
      for (int i = 0; i < 40; ++i) {
        start.height.at(i, j) = 0.01 + 1e-4 * u(rng);
        if (u(rng) < 0.8) start.erosion.touch(model.cell(i, j));
      }
    }
    for (int b = 0; b < 6; ++b) {
      start.height.at(static_cast<int>(40 * u(rng)), static_cast<int>(30 * u(rng))) += 0.03 * u(rng);
    }
    Underside plate;
    plate.footprint = Footprint{10, 5, 12, 15};
    plate.z_m = ArrayXXdR::Constant(15, 12, 0.004 + 0.01 * u(rng));
    Ceiling ceiling;
    ceiling.undersides.push_back(plate);
    GroundState restricted = start, swept = start;
    for (int step = 0; step < 4; ++step) {
      m.erosion_iterations = 6;
      erode(model, GroundParams{{m}}, ceiling, &restricted);
      m.erosion_iterations = 1;
      for (int p = 0; p < 6; ++p) erode(model, GroundParams{{m}}, ceiling, &swept);
      restricted.erosion.end_step();
      swept.erosion.end_step();
    }
    EXPECT_GT((swept.height.heights() != start.height.heights()).count(), 4) << seed;  // it did erode
    EXPECT_TRUE((restricted.height.heights() == swept.height.heights()).all()) << seed;
    EXPECT_EQ(restricted.erosion.cells(), swept.erosion.cells()) << seed;
  }
}

// erode()'s level-bed passes written plainly (erosion.h): every remembered
// cell in memory order, its neighbours at +x, -x, +y, -y, each pair once
// (a remembered neighbour before the cell in storage visits the pair
// itself); a flux sigma * (dh - cell tan(theta)) from the higher cell where
// that exceeds the tolerance; the inflow of a cell under the ceiling summed
// in flux order and scaled to its room; the moves applied in flux order,
// then both cells of each remembered.
void plain_passes(const GroundModel& model, const Material& m, const Ceiling& ceiling, GroundState* state) {
  const Grid& g = model.grid;
  const double max_dh = g.cell_size_m * std::tan(m.repose_angle_rad), tol = kErosionToleranceFraction * g.cell_size_m;
  double* h = state->height.heights().data();
  struct Move {
    std::int64_t from, to;
    double amount, ceiling_m;
  };
  for (int p = 0; p < m.erosion_iterations; ++p) {
    std::vector<Move> moves;
    for (const std::int64_t c : state->erosion.cells()) {
      const int i = static_cast<int>(c % g.nx), j = static_cast<int>(c / g.nx);
      for (const auto& [di, dj] : {std::pair{1, 0}, {-1, 0}, {0, 1}, {0, -1}}) {
        if (!g.contains(i + di, j + dj)) continue;
        const std::int64_t n = model.cell(i + di, j + dj);
        if (n < c && state->erosion.contains(n)) continue;
        const bool c_higher = h[c] > h[n];
        const double excess = std::abs(h[c] - h[n]) - max_dh;
        if (!(excess > tol)) continue;
        moves.push_back({c_higher ? c : n, c_higher ? n : c, m.sigma * excess,
                         c_higher ? ceiling.at(i + di, j + dj) : ceiling.at(i, j)});
      }
    }
    if (moves.empty()) return;
    std::map<std::int64_t, double> inflow;
    for (const Move& f : moves) {
      if (std::isfinite(f.ceiling_m)) inflow[f.to] += f.amount;
    }
    for (Move& f : moves) {
      const double allowed = std::max(0.0, f.ceiling_m - h[f.to]);
      if (std::isfinite(f.ceiling_m) && inflow[f.to] > allowed) f.amount *= allowed / inflow[f.to];
    }
    for (const Move& f : moves) {
      if (f.amount > 0.0) h[f.from] -= f.amount, h[f.to] += f.amount;
    }
    for (const Move& f : moves) {
      if (f.amount > 0.0) state->erosion.touch(f.from), state->erosion.touch(f.to);
    }
  }
}

// The scan erode() runs (erosion.cpp: the pairs over the limit found first,
// their fluxes made after) moves what the plain one does, to the bit, in
// the same order: the same heights and the same memory, cell for cell.
TEST(Erosion, ErodeMovesWhatAPlainScanOfTheRememberedPairsMoves) {
  for (const unsigned seed : {1u, 2u, 3u}) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    Material m = sand();
    m.sigma = 0.1 + 0.15 * u(rng);
    m.erosion_iterations = 5;
    const GroundModel model = make_plain_ground_model(centred_grid(23, 17, 0.01), m);
    GroundState start = make_ground_state(model, HeightField(model.grid, 0.0));
    for (int j = 0; j < 17; ++j) {  // rough, every cell's slopes over the limit or not, the memory in random order
      for (int i = 0; i < 23; ++i) start.height.at(i, j) = 0.02 * u(rng);
    }
    for (int k = 0; k < 300; ++k) start.erosion.touch(static_cast<std::int64_t>(23 * 17 * u(rng)));
    Underside plate;
    plate.footprint = Footprint{6, 4, 8, 7};
    plate.z_m = ArrayXXdR::Constant(7, 8, 0.012);
    Ceiling ceiling;
    ceiling.undersides.push_back(plate);
    GroundState scanned = start, plain = start;
    for (int step = 0; step < 3; ++step) {
      erode(model, GroundParams{{m}}, ceiling, &scanned);
      plain_passes(model, m, ceiling, &plain);
      scanned.erosion.end_step();
      plain.erosion.end_step();
    }
    EXPECT_GT((plain.height.heights() != start.height.heights()).count(), 20) << seed;  // it did erode
    EXPECT_TRUE((scanned.height.heights() == plain.height.heights()).all()) << seed;
    EXPECT_EQ(scanned.erosion.cells(), plain.erosion.cells()) << seed;
  }
}

// A cell under an object fed from both sides, with room for less than both
// bring: it fills exactly to the ceiling, and both sources give in
// proportion to what they would have given (each flux scaled alike).
TEST(Erosion, ACappedCellSharesItsRoomAmongItsInflows) {
  Material m = sand();
  m.erosion_iterations = 1;  // one pass: the fluxes of the starting heights
  const GroundModel model = make_plain_ground_model(centred_grid(5, 1, 0.01), m);
  GroundState state = make_ground_state(model, HeightField(model.grid, 0.0));
  const double start[5] = {0.05, 0.05, 0.0, 0.03, 0.03};
  for (int i = 0; i < 5; ++i) {
    state.height.at(i, 0) = start[i];
    state.erosion.touch(model.cell(i, 0));
  }
  const double ceiling_m = 0.004;
  Underside plate;
  plate.footprint = Footprint{2, 0, 1, 1};
  plate.z_m = ArrayXXdR::Constant(1, 1, ceiling_m);
  Ceiling ceiling;
  ceiling.undersides.push_back(plate);
  erode(model, GroundParams{{m}}, ceiling, &state);

  const double max_dh = 0.01 * std::tan(m.repose_angle_rad);
  const double left = m.sigma * (start[1] - max_dh), right = m.sigma * (start[3] - max_dh);
  ASSERT_GT(left + right, ceiling_m);  // the room is what limits
  EXPECT_NEAR(state.height.at(2, 0), ceiling_m, 1e-15);
  const double given_left = start[1] - state.height.at(1, 0), given_right = start[3] - state.height.at(3, 0);
  EXPECT_NEAR(given_left, ceiling_m * left / (left + right), 1e-15);
  EXPECT_NEAR(given_right, ceiling_m * right / (left + right), 1e-15);
  EXPECT_EQ(state.height.at(0, 0), start[0]);
  EXPECT_EQ(state.height.at(4, 0), start[4]);
}

// The inflow scratch that capping sums into (erosion_scratch.h) is all 0
// after every call, so no result depends on the state it is kept in: a
// state whose scratch has served many capped passes erodes like a fresh copy
// of the same heights, bit for bit.
TEST(Erosion, TheInflowScratchIsClearAfterEveryCall) {
  Material m = sand();
  m.erosion_iterations = 3;
  const GroundModel model = make_plain_ground_model(centred_grid(16, 16, 0.01), m);
  GroundState used = column(model, 0.0, 0.1, 3);
  Underside plate;
  plate.footprint = Footprint{8, 0, 8, 16};
  plate.z_m = ArrayXXdR::Constant(16, 8, 0.01);
  Ceiling ceiling;
  ceiling.undersides.push_back(plate);
  for (int s = 0; s < 5; ++s) {
    erode(model, GroundParams{{m}}, ceiling, &used);
    ASSERT_EQ(used.erosion_scratch.inflow_m.size(), model.grid.cell_count());
    for (const double v : used.erosion_scratch.inflow_m) ASSERT_EQ(v, 0.0) << s;
  }
  double highest = 0.0;  // under the plate, beside the column: capping ran (the room is what limits)
  for (int j = 0; j < 16; ++j) {
    for (int i = 11; i < 16; ++i) highest = std::max(highest, used.height.at(i, j));
  }
  EXPECT_LE(highest, 0.01 + 1e-15);
  EXPECT_GT(highest, 0.009);
  GroundState fresh = make_ground_state(model, used.height);
  fresh.erosion = used.erosion;
  erode(model, GroundParams{{m}}, ceiling, &used);
  erode(model, GroundParams{{m}}, ceiling, &fresh);
  EXPECT_TRUE((used.height.heights() == fresh.height.heights()).all());
}

TEST(Erosion, MemoryForgetsSettledCells) {
  const Material m = sand();
  GroundModelSpec options;
  options.erosion_memory_steps = 3;
  const GroundModel model = make_plain_ground_model(centred_grid(8, 8, 0.01), m, options);
  GroundState state = make_ground_state(model, HeightField(model.grid, 0.0));
  state.erosion.touch(model.cell(4, 4));  // flat: nothing moves
  for (int s = 0; s < 4; ++s) {
    EXPECT_FALSE(state.erosion.empty()) << s;
    erode(model, GroundParams{{m}}, Ceiling{}, &state);
    state.erosion.end_step();
  }
  EXPECT_TRUE(state.erosion.empty());
}

// The stability limit, measured: a rough (checkerboard) surface with theta
// near 0 keeps its roughness bounded for sigma up to 1/4 and blows up above.
double roughness_growth(double sigma) {
  Material m = sand();
  m.repose_angle_rad = 0.1 * kDeg;
  m.sigma = sigma;
  m.erosion_iterations = 1;
  const GroundModel model = make_plain_ground_model(centred_grid(16, 16, 0.01), m);
  GroundState state = make_ground_state(model, HeightField(model.grid, 0.0));
  for (int j = 0; j < 16; ++j) {
    for (int i = 0; i < 16; ++i) {
      state.height.at(i, j) = ((i + j) % 2 ? 1e-3 : -1e-3) * (1.0 + 0.01 * i);
      state.erosion.touch(model.cell(i, j));
    }
  }
  const double before = max_slope(state.height);
  for (int s = 0; s < 200; ++s) erode(model, GroundParams{{m}}, Ceiling{}, &state);
  EXPECT_TRUE(state.height.all_finite());
  return max_slope(state.height) / before;
}

TEST(ErosionStability, BoundedUpToSigmaMaxDivergesAbove) {
  for (const double sigma : {0.05, 0.125, 0.2, 0.24}) EXPECT_LT(roughness_growth(sigma), 1.0) << sigma;
  EXPECT_LE(roughness_growth(kSigmaMax), 1.0 + 1e-9);
  for (const double sigma : {0.3, 0.5}) EXPECT_GT(roughness_growth(sigma), 1e3) << sigma;
}

TEST(ErosionStability, ValidateRefusesSigmaAboveTheLimit) {
  Material m = sand();
  m.sigma = 0.3;
  const GroundModel model = make_plain_ground_model(centred_grid(4, 4, 0.01), m);
  try {
    validate(GroundParams{{m}}, model);
    FAIL() << "sigma 0.3 accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("sigma"), std::string::npos) << e.what();
  }
}

// Inclined bed (erosion.h): a chute of `cells` along x (bed-aligned, the bed
// falling along +x by slope_deg), `rows` across, its first `block_cells`
// holding a block of height block_m, all remembered by make_ground_state.
struct Chute {
  GroundModel model;
  GroundState state;
};

Chute chute(double slope_deg, double theta_deg, double sigma, int cells, int rows, int block_cells, double block_m) {
  Material m = sand();
  m.repose_angle_rad = theta_deg * kDeg;
  m.sigma = sigma;
  GroundModelSpec options;
  options.bed_slope_rad = slope_deg * kDeg;
  options.erosion_memory_steps = 2;
  GroundModel model = make_plain_ground_model(centred_grid(cells, rows, 0.005), m, options);
  HeightField h(model.grid, 0.0);
  for (int j = 0; j < rows; ++j) {
    for (int i = 0; i < block_cells; ++i) h.at(i, j) = block_m * (1.0 + 0.05 * j);
  }
  GroundState state = make_ground_state(model, std::move(h));
  return {std::move(model), std::move(state)};
}

// Settles with end_step asking is_settled, as ground_step does; checks after
// every pass that no height goes below the bed. Returns the steps taken.
int settle_inclined(const GroundModel& model, GroundState* state, int max_steps) {
  const GroundParams params{model.materials};
  const std::vector<double> max_dh = max_height_differences(model, params);
  int s = 0;
  for (; s < max_steps && !state->erosion.empty(); ++s) {
    erode(model, params, Ceiling{}, state);
    EXPECT_GE(state->height.min_height_m(), 0.0) << "step " << s;
    state->erosion.end_step([&](std::int64_t c) { return is_settled(model, max_dh, state->height, c); });
  }
  return s;
}

// Every pair of a settled surface, both cells holding material, lies within
// the world-frame repose rule: along x atan(d / cell) - slope in [-theta,
// theta], across |d| cos(slope) <= cell tan(theta) (to the tolerance).
void expect_within_the_inclined_rule(const HeightField& h, double slope_deg, double theta_deg) {
  const double c = h.grid().cell_size_m, tol = 1.01 * kErosionToleranceFraction * c;
  const double zeta = slope_deg * kDeg, theta = theta_deg * kDeg;
  for (int j = 0; j < h.grid().ny; ++j) {
    for (int i = 0; i < h.grid().nx; ++i) {
      if (i + 1 < h.grid().nx && h.at(i, j) > 0.0 && h.at(i + 1, j) > 0.0) {
        const double d = h.at(i + 1, j) - h.at(i, j);
        EXPECT_GE(d, c * std::tan(zeta - theta) - tol) << i << "," << j;
        if (zeta + theta < std::numbers::pi / 2) { EXPECT_LE(d, c * std::tan(zeta + theta) + tol) << i << "," << j; }
      }
      if (j + 1 < h.grid().ny && h.at(i, j) > 0.0 && h.at(i, j + 1) > 0.0) {
        EXPECT_LE(std::abs(h.at(i, j + 1) - h.at(i, j)) * std::cos(zeta), c * std::tan(theta) + tol) << i << "," << j;
      }
    }
  }
}

TEST(InclinedErosion, SettledSurfacesKeepTheWorldAngleOfReposeAndTheirVolume) {
  for (const auto& [slope_deg, theta_deg] :
       {std::pair{10.0, 30.0}, std::pair{35.0, 30.0}, std::pair{35.0, 40.0}, std::pair{45.0, 38.0},
        std::pair{60.0, 35.0}}) {
    for (const double sigma : {0.1, 0.25}) {
      Chute c = chute(slope_deg, theta_deg, sigma, 60, 3, 12, 0.06);
      const double volume = c.state.height.volume_m3();
      ASSERT_LT(settle_inclined(c.model, &c.state, 200000), 200000) << slope_deg << " " << theta_deg;
      SCOPED_TRACE(::testing::Message() << slope_deg << " deg bed, " << theta_deg << " deg, sigma " << sigma);
      expect_within_the_inclined_rule(c.state.height, slope_deg, theta_deg);
      EXPECT_NEAR(c.state.height.volume_m3(), volume, 1e-12 * volume);
      EXPECT_TRUE(c.state.height.all_finite());
    }
  }
}

// Steeper than its angle of repose, the block leaves the top of the chute
// and piles against its closed lower end, the pile's surface rising toward
// the end (d >= cell tan(slope - theta) > 0): at the least rise, a wedge of
// the block's area A ends at the height sqrt(2 A tan(slope - theta)). Below
// it, the block's front slumps down the chute and its back stays in place.
TEST(InclinedErosion, ABlockSteeperThanReposeRunsDownAndPilesAgainstTheEnd) {
  Chute steep = chute(35.0, 30.0, 0.2, 150, 1, 20, 0.1);
  settle_inclined(steep.model, &steep.state, 200000);
  const HeightField& h = steep.state.height;
  EXPECT_LT(h.at(0, 0), 1e-6);  // the top drained
  const double wedge_end_m = std::sqrt(2.0 * (20 * 0.005 * 0.1) * std::tan(5.0 * kDeg));
  EXPECT_NEAR(h.at(149, 0), wedge_end_m, 0.1 * wedge_end_m);
  for (int i = 0; i + 1 < 150; ++i) {
    if (h.at(i, 0) > 0.0) { EXPECT_GT(h.at(i + 1, 0), h.at(i, 0)) << i; }
  }
  Chute gentle = chute(35.0, 60.0, 0.2, 80, 1, 40, 0.02);
  settle_inclined(gentle.model, &gentle.state, 200000);
  EXPECT_EQ(gentle.state.height.at(0, 0), 0.02);  // held by the rule along the block
  EXPECT_GT(gentle.state.height.at(42, 0), 0.0);  // the front slumped down the chute
  EXPECT_EQ(gentle.state.height.at(79, 0), 0.0);  // and stopped
}

// A uniform layer on a bed gentler than the angle of repose is at rest:
// nothing moves and the memory empties; on a steeper bed it flows.
TEST(InclinedErosion, AUniformLayerRestsBelowTheAngleOfReposeAndFlowsAbove) {
  for (const auto& [slope_deg, moves] : {std::pair{25.0, false}, std::pair{35.0, true}}) {
    Chute c = chute(slope_deg, 30.0, 0.2, 20, 1, 20, 0.01);
    const ArrayXXdR before = c.state.height.heights();
    settle_inclined(c.model, &c.state, 5);
    EXPECT_EQ((c.state.height.heights() != before).any(), moves) << slope_deg;
    EXPECT_EQ(!c.state.erosion.empty(), moves) << slope_deg;
  }
}

}  // namespace
}  // namespace repose
