#!/bin/bash
# Renders the independent references of src/test/resources/reference-pt/ made with Mitsuba 3 (see its
# README): for each scene named, the high-spp image (written beside the scene) and two 256-spp runs
# (seeds 1 and 2, into $OUT), and prints the bound: FACTOR x the worse 256-spp run's relMSE and mean
# 8-bit error against the high-spp image (FACTOR 1.5, or 2 where rough glass is).
#
#   python3 -m venv /tmp/mi && /tmp/mi/bin/pip install mitsuba numpy pyyaml   # Mitsuba 3.9 (lab only: not part of the product)
#   apt-get install -y libllvm19                                             # for the llvm_ad_rgb variant
#   PYTHON=/tmp/mi/bin/python scripts/mitsuba/make-references.sh 16384 sun-disc:1.5 frosted-pair:2 ...
set -euo pipefail
HERE=$(cd "$(dirname "$0")" && pwd)
REFS=$HERE/../../src/test/resources/reference-pt
PYTHON=${PYTHON:-python3}
OUT=${OUT:-/tmp/glint-mitsuba}
export DRJIT_LIBLLVM_PATH=${DRJIT_LIBLLVM_PATH:-$(ls /usr/lib/*/libLLVM-19.so /usr/lib/*/libLLVM.so.19* 2>/dev/null | head -1)}
SPP=$1
shift
mkdir -p "$OUT"
for arg in "$@"; do
  scene=${arg%%:*}
  factor=${arg#*:}
  "$PYTHON" "$HERE/glint2mitsuba.py" "$REFS/$scene.yaml" "$REFS/$scene.pfm" --width 200 --height 150 --spp "$SPP" --seed 7
  for seed in 1 2; do
    "$PYTHON" "$HERE/glint2mitsuba.py" "$REFS/$scene.yaml" "$OUT/$scene-256-s$seed.pfm" --width 200 --height 150 --spp 256 --seed $seed
  done
  "$PYTHON" "$HERE/errors.py" --bound "$factor" "$REFS/$scene.pfm" "$OUT/$scene-256-s1.pfm" "$OUT/$scene-256-s2.pfm"
done
