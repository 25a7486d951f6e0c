#!/usr/bin/env bash
# The main job on the default experiment. Results go to runs/default/ (replaced).
set -euo pipefail
cd "$(dirname "$0")/.."
build/bin/repose run experiments/scenes/default_ground.yaml --out runs/default --force
echo "main job: results in runs/default/ (manifest.json, height fields, images)"
