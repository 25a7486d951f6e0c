#!/usr/bin/env bash
# The main job: calibrate the ground model against the committed canonical
# LIGGGHTS runs (data/) with the default calibration file. Results go to
# runs/calibration_default/ (replaced only once the new run succeeded).
set -euo pipefail
cd "$(dirname "$0")/.."
build/bin/repose calibrate experiments/calibration_default.yaml --out runs/calibration_default --force
echo "main job: read runs/calibration_default/report.md first (calibration.json, parameters.yaml, figures beside it)"
