#!/usr/bin/env bash
# Installs the Debian packages repose builds and runs with; skips what is
# already installed, so a second call costs a second.
set -euo pipefail

packages=(
  build-essential cmake pkg-config git
  libbullet-dev libode-dev libeigen3-dev libceres-dev libcgal-dev
  libosmesa6-dev libembree-dev
  liggghts libliggghts-dev liggghts-doc mpi-default-dev openmpi-bin
  libyaml-cpp-dev libcli11-dev libfmt-dev libpng-dev nlohmann-json3-dev ccache
  libgtest-dev libgmock-dev libbenchmark-dev clang libclang-rt-14-dev
  python3-matplotlib python3-numpy python3-yaml
  # the paper (scripts/make-paper.sh): LaTeX, latexmk, pdftoppm/pdfinfo
  texlive-latex-base texlive-latex-recommended texlive-fonts-recommended latexmk poppler-utils
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi

echo "install-deps: installing ${#missing[@]} missing packages: ${missing[*]}"
SUDO=""
[ "$(id -u)" -eq 0 ] || SUDO="sudo"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
echo "install-deps: done"
