#!/usr/bin/env bash
# Times Glint against POV-Ray 3.7 on the same picture, taking turns: the spec's example scene
# (scenes/bench/spec-example.yaml) at 800x600, one ray a pixel, 5 levels, 2 threads
# (scripts/pov/spec-example.pov is its POV-Ray twin). Each round
# renders the twin once (its trace CPU-seconds) and runs a --bench 40 of Glint (the median render CPU
# of its last 20 frames, once the JIT has compiled the renderer), then prints the median of the
# rounds' ratios POV-Ray / Glint.
# Usage, from the repository root after `mvn -q package -DskipTests`: scripts/povray-twin.sh [ROUNDS]
# Needs povray (apt-get install povray). Lab only: not part of the product.
set -euo pipefail
rounds=${1:-8}
cd "$(dirname "$0")/.."
config=$(mktemp --suffix=.properties)
scene=$(mktemp --suffix=.yaml)
trap 'rm -f "$config" "$scene"' EXIT
sed 's/^min_weight=.*/min_weight=0/' config.properties > "$config"   # both trace every ray
sed '/^views:/,/^objects:/{/^objects:/!d}' scenes/bench/spec-example.yaml > "$scene"
ratios=()
for ((i = 1; i <= rounds; i++)); do
  pov=$(povray +Iscripts/pov/spec-example.pov +W800 +H600 -A +WT2 -D -F 2>&1 \
        | sed -n '/Trace Time/{n;s/.* with \([0-9.]*\) CPU-seconds.*/\1/p}')
  glint=$(java -jar target/glint.jar --config "$config" --scene "$scene" --width 800 --height 600 --spp 1 \
          --depth 5 --threads 2 --bench 40 | sed -n 's/^frame [0-9]*: .* render cpu \([0-9.]*\) ms$/\1/p' \
          | tail -20 | sort -n | sed -n 10p)
  ratio=$(awk -v p="$pov" -v g="$glint" 'BEGIN { printf "%.2f", 1000 * p / g }')
  echo "round $i: POV-Ray trace ${pov} s CPU, Glint ${glint} ms render CPU a frame: ${ratio}x"
  ratios+=("$ratio")
done
printf '%s\n' "${ratios[@]}" | sort -n | awk '{ a[NR] = $1 } END { m = (NR % 2) ? a[(NR + 1) / 2] : (a[NR / 2] + a[NR / 2 + 1]) / 2;
  printf "median POV-Ray / Glint: %.2fx (range %.2f-%.2f, %d rounds)\n", m, a[1], a[NR], NR }'
