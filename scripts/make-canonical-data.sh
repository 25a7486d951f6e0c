#!/usr/bin/env bash
# Regenerates the canonical reference runs in data/ (see data/README.md):
# each scene below is run with
#   repose run SCENE --solver liggghts --out RUNS/NAME
# (or bullet or ode, for the names listed in `solvers`)
# one after the other (LIGGGHTS is serial and niced by the runner), and only
# the small files (manifests, observables as .npy/.csv, the input script and
# the log) are copied into data/NAME/; dumps, restart files and meshes stay
# in RUNS. Settled beds are cached (REPOSE_CACHE, default REPO/cache), so a
# second call only re-runs the scenes.
#
# usage: scripts/make-canonical-data.sh [NAME ...]     (default: every canonical run)
#        NAME is a folder under data/: dem_indent, ref_bulldoze/seed2, ...
# environment: REPOSE  the repose program (default: REPO/build-dem/bin/repose,
#                      else REPO/build/bin/repose)
#              RUNS    where full run folders go (default: REPO/runs/canonical)
#              NICE    niceness of repose (default 19; LIGGGHTS runs 10 above it, at most 19)
set -euo pipefail

repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
runs="${RUNS:-$repo/runs/canonical}"
repose="${REPOSE:-}"
if [[ -z "$repose" ]]; then
  for candidate in "$repo/build-dem/bin/repose" "$repo/build/bin/repose"; do
    if [[ -x "$candidate" ]]; then repose="$candidate"; break; fi
  done
fi
if [[ -z "$repose" || ! -x "$repose" ]]; then
  echo "make-canonical-data: no repose program; build it (cmake --build BUILD --target repose) or set REPOSE" >&2
  exit 2
fi

# the manifests in data/ name the settled bed's folder: relative when the
# cache is inside the repository, by an absolute path (which the tests refuse
# in committed data) when it is not
if [[ -n "${REPOSE_CACHE:-}" && "$(realpath -m "$REPOSE_CACHE")/" != "$repo"/* ]]; then
  echo "make-canonical-data: REPOSE_CACHE=$REPOSE_CACHE is outside the repository, so data/ would hold its absolute path; unset it (REPO/cache) or copy the beds into REPO/cache" >&2
  exit 2
fi

# name -> scene (relative to the repository) and, for the scale-separated
# references, the seed of the random bed (`--set seed=N`): NAME/seedN.
declare -A scenes=(
  [dem_indent]=experiments/scenes/dem_indent.yaml
  [dem_indent_r3mm]=experiments/scenes/dem_indent_r3mm.yaml
  [dem_drag]=experiments/scenes/dem_drag.yaml
  [dem_drag_box]=experiments/scenes/dem_drag_box.yaml
  [dem_pile]=experiments/scenes/dem_pile.yaml
)
seeds=(1 2 3)
# the scale-separated references (issue 10): press bed, then drag bed, so
# that scenes sharing a settled bed follow each other
reference_scenes=(ref_indent_shallow ref_indent_deep ref_drag_sphere ref_bulldoze ref_cylinder_side ref_tilted_box ref_pile)
order=(dem_indent dem_indent_r3mm dem_drag dem_drag_box dem_pile)
for seed in "${seeds[@]}"; do
  for scene in "${reference_scenes[@]}"; do
    scenes[$scene/seed$seed]=experiments/scenes/$scene.yaml
    order+=("$scene/seed$seed")
  done
done
# the coarse-grain LIGGGHTS rung of the default calibration's ladder: one bed
scenes[ref_indent_deep_coarse/seed1]=experiments/scenes/ref_indent_deep_coarse.yaml
order+=(ref_indent_deep_coarse/seed1)
# the rigid-body engines' rungs of the same ladder (issue 11): the reference's
# scene and first bed in Bullet and ODE
declare -A solvers=()
for engine in bullet ode; do
  scenes[ref_indent_deep_$engine/seed1]=experiments/scenes/ref_indent_deep.yaml
  solvers[ref_indent_deep_$engine/seed1]=$engine
  order+=("ref_indent_deep_$engine/seed1")
done
# the scoop references (issue 12): LIGGGHTS and Bullet on three beds each,
# the calibration's held-out shallower scoop and a scoop of middle depth in
# LIGGGHTS on the same beds
for seed in "${seeds[@]}"; do
  scenes[ref_scoop/seed$seed]=experiments/scenes/ref_scoop.yaml
  scenes[ref_scoop_shallow/seed$seed]=experiments/scenes/ref_scoop_shallow.yaml
  scenes[ref_scoop_medium/seed$seed]=experiments/scenes/ref_scoop_medium.yaml
  scenes[ref_scoop_bullet/seed$seed]=experiments/scenes/ref_scoop.yaml
  solvers[ref_scoop_bullet/seed$seed]=bullet
  order+=("ref_scoop/seed$seed")
done
for seed in "${seeds[@]}"; do order+=("ref_scoop_shallow/seed$seed" "ref_scoop_bullet/seed$seed"); done
for seed in "${seeds[@]}"; do order+=("ref_scoop_medium/seed$seed"); done
# the LIGGGHTS scoops at the three depths on four more beds (seeds 4-7): the
# seed-to-seed scatter of the held mass and the dumped heap's flank, the
# held-out targets' yardsticks, from seven beds rather than three (issue 12)
for seed in 4 5 6 7; do
  for scene in ref_scoop_shallow ref_scoop ref_scoop_medium; do
    scenes[$scene/seed$seed]=experiments/scenes/$scene.yaml
    order+=("$scene/seed$seed")
  done
done
# the held-out shallow scoop on seven beds more (seeds 8-14): the mean its
# held masses are judged against, to a standard error of about 1.1 % rather
# than 1.6 % (one bed differs from the mean by up to 7 %; issue 12)
for seed in 8 9 10 11 12 13 14; do
  scenes[ref_scoop_shallow/seed$seed]=experiments/scenes/ref_scoop_shallow.yaml
  order+=("ref_scoop_shallow/seed$seed")
done
# the coarse-grain rungs of the scoop's ladder (grains 1.5 times larger): one bed per engine
scenes[ref_scoop_coarse/seed1]=experiments/scenes/ref_scoop_coarse.yaml
scenes[ref_scoop_coarse_bullet/seed1]=experiments/scenes/ref_scoop_coarse.yaml
solvers[ref_scoop_coarse_bullet/seed1]=bullet
order+=(ref_scoop_coarse/seed1 ref_scoop_coarse_bullet/seed1)
# the cohesive DEM snowfall references of the snow calibration (issue 13):
# the fit scene (a table top and a step) and the held-out one (a house under
# an overhanging roof), each on three seeds, at three cohesion levels
# (J/m^3, `--set dem.cohesion_energy_density_j_m3=C`): NAME_cC/seedN.
# Cohesive grains keep a jitter of ~1e-6 J after their shape is set (sjkr
# cohesion is undamped), so they count as settled below 3e-6 J.
# The _deep scenes rain 4 cm (10 grain diameters) instead of 1 cm (2.5), deep
# enough for flanks at the grains' angle; the snow calibrations use those.
declare -A sets=()
for cohesion in 0 1e5 3e5; do
  for scene in snowfall_table_deep snowfall_roof_deep snowfall_table snowfall_roof; do
    for seed in "${seeds[@]}"; do
      name="${scene}_c$cohesion/seed$seed"
      scenes[$name]=experiments/scenes/$scene.yaml
      sets[$name]="dem.cohesion_energy_density_j_m3=$cohesion"
      if [[ "$cohesion" != 0 ]]; then sets[$name]+=" dem.settle_kinetic_energy_j=3e-6"; fi
      order+=("$name")
    done
  done
done
# the dry heap scene of the snow angle of repose (issue 13): a plate 24 cm
# (60 grains) wide, endless along y, under 4 cm of vertical snowfall; the
# ridge on it is ~10 grains tall (experiments/snow_calibration_c0_ridge.yaml)
for seed in "${seeds[@]}"; do
  name="snowfall_ridge_c0/seed$seed"
  scenes[$name]=experiments/scenes/snowfall_ridge.yaml
  order+=("$name")
done
# the rock-scale chute of the Bullet calibration (issue 14, item 6): the fit
# slope (35 deg) and the held-out one (45 deg) in LIGGGHTS, the reference,
# and in Bullet with its default contact parameters (the unfitted rung), on
# three beds each
for scene in chute_rock chute_rock_45; do
  for seed in "${seeds[@]}"; do
    scenes[$scene/seed$seed]=experiments/scenes/$scene.yaml
    scenes[${scene}_bullet/seed$seed]=experiments/scenes/$scene.yaml
    solvers[${scene}_bullet/seed$seed]=bullet
    order+=("$scene/seed$seed" "${scene}_bullet/seed$seed")
  done
done
# the debris flow on generated terrain against two buildings (issue 14,
# item 4): each engine on three random beds (the elements' radii and
# placement drawn from the seed), LIGGGHTS' the reference and its noise
for seed in "${seeds[@]}"; do
  scenes[terrain_debris/seed$seed]=experiments/scenes/terrain_debris.yaml
  order+=("terrain_debris/seed$seed")
  for engine in bullet ode; do
    scenes[terrain_debris_$engine/seed$seed]=experiments/scenes/terrain_debris.yaml
    solvers[terrain_debris_$engine/seed$seed]=$engine
    order+=("terrain_debris_$engine/seed$seed")
  done
done
if [[ $# -gt 0 ]]; then order=("$@"); fi

# the files kept in data/NAME (the rest of the run folder is large or
# regenerable): the records every LIGGGHTS run writes, and a rigid-body
# engine's manifest (bullet_manifest.json or ode_manifest.json)
keep_liggghts=(manifest.json liggghts_manifest.json bed_manifest.json run.in log.liggghts)
keep_snowfall=(manifest.json liggghts_manifest.json snowfall.in log.liggghts)  # no settled bed: the grains rain
shopt -s nullglob

for name in "${order[@]}"; do
  scene="${scenes[$name]:-}"
  if [[ -z "$scene" ]]; then
    echo "make-canonical-data: unknown run '$name' (known: ${!scenes[*]})" >&2
    exit 2
  fi
  echo "== $name: $scene"
  mkdir -p "$runs"
  set_seed=()
  if [[ "$name" == */seed* ]]; then set_seed=(--set "seed=${name##*/seed}"); fi
  for assignment in ${sets[$name]:-}; do set_seed+=(--set "$assignment"); done
  solver="${solvers[$name]:-liggghts}"
  nice -n "${NICE:-19}" "$repose" run "$repo/$scene" --solver "$solver" --out "$runs/$name" --force "${set_seed[@]}"
  target="$repo/data/$name"
  mkdir -p "$(dirname "$target")"
  rm -rf "$target.tmp"
  mkdir -p "$target.tmp"
  if [[ -f "$runs/$name/front.csv" ]]; then  # a debris flow (validation/rigid/debris_run.h): no bed, frames stay in RUNS
    cp "$runs/$name/manifest.json" "$runs/$name/parts.json" "$target.tmp/"
    for f in debris.in log.liggghts; do if [[ -f "$runs/$name/$f" ]]; then cp "$runs/$name/$f" "$target.tmp/"; fi; done
  elif [[ "$solver" == liggghts && -f "$runs/$name/snowfall.in" ]]; then
    for f in "${keep_snowfall[@]}"; do cp "$runs/$name/$f" "$target.tmp/"; done
  elif [[ "$solver" == liggghts ]]; then
    for f in "${keep_liggghts[@]}"; do cp "$runs/$name/$f" "$target.tmp/"; done
  else
    cp "$runs/$name/manifest.json" "$runs/$name/${solver}_manifest.json" "$target.tmp/"
  fi
  cp "$runs/$name"/*.npy "$runs/$name"/*.csv "$target.tmp/"
  rm -f "$target.tmp"/grains_*.npy  # the grains themselves: large, and not an observable
  rm -rf "$target"
  mv "$target.tmp" "$target"
  du -sh "$target"
done
du -sh "$repo/data"
