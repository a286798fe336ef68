#!/bin/sh
# What a still pass of the window costs against a headless sample pass of the same size and settings,
# measured side by side in one run (docs/records/window.md, "Refinement cost"). ROUNDS times in turn:
#  - headless: --bench 8 and --bench 4 at 16 samples per pixel; a sample pass is the median of frames
#    3 to 8 divided by 16 (wall clock), and the difference of the two runs' CPU time divided by 4 x 16
#    (CPU, JVM start and JIT warm-up left out);
#  - the window under Xvfb, refining the same view to 256 samples and to 64: a pass is its debug=true
#    line's wall-clock time of the last 192 passes divided by 192, and the difference of the two runs'
#    process CPU time at that line divided by 192 (encoding and painting included; the X server's own
#    work not).
# Needs xvfb-run. Usage, from anywhere after `mvn -q package -DskipTests`:
#   scripts/refine-cost.sh [WIDTH HEIGHT [SCENE [ROUNDS]]]     (default: 800 600 scenes/bench/matte-5.yaml 3)
set -e
cd "$(dirname "$0")/.."
if [ -z "$REFINE_COST_INSIDE" ]; then
    REFINE_COST_INSIDE=1 exec xvfb-run -a -s "-screen 0 1600x1200x24" "$0" "$@"
fi
w=${1:-800}
h=${2:-600}
scene=${3:-scenes/bench/matte-5.yaml}
rounds=${4:-3}
out=target/refine-cost
mkdir -p "$out"
printf 'debug=true\n' > "$out/debug.properties"
hz=$(getconf CLK_TCK)
headless() { # frames; prints the median ms of frames 3.. divided by 16, then the CPU seconds
    /usr/bin/time -f 'cpu %U %S' -o "$out/time.log" java -jar target/glint.jar --config "$out/debug.properties" \
        --scene "$scene" --width "$w" --height "$h" --spp 16 --bench "$1" 2>/dev/null | grep '^frame' | tail -n +3 \
        | sed 's/frame [0-9]*: \([0-9.]*\) ms.*/\1/' | sort -n | awk '{a[NR] = $1} END {print (a[int((NR + 1) / 2)] + a[int(NR / 2) + 1]) / 2 / 16}'
    awk '{print $2 + $3}' "$out/time.log"
}
window() { # samples; prints the ms a pass of the debug line, then the process's CPU seconds at that line
    rm -f "$out/window.log"
    java -jar target/glint.jar --config "$out/debug.properties" --scene "$scene" --width "$w" --height "$h" \
        --spp "$1" 2> "$out/window.log" > /dev/null &
    pid=$!
    n=0
    while ! grep -q 'window refined' "$out/window.log" 2>/dev/null && [ $n -lt 1200 ]; do sleep 0.1; n=$((n + 1)); done
    cpu=$(awk -v hz="$hz" '{print ($14 + $15) / hz}' "/proc/$pid/stat")
    kill "$pid"; wait "$pid" || true
    sed -n 's/.*: \([0-9.]*\) ms a pass.*/\1/p' "$out/window.log"
    echo "$cpu"
}
for i in $(seq "$rounds"); do
    set -- $(headless 8) $(headless 4) $(window 256) $(window 64)
    awk -v i="$i" -v hw="$1" -v h8="$2" -v h4="$4" -v ww="$5" -v w256="$6" -v w64="$8" 'BEGIN {
        hc = (h8 - h4) * 1000 / 64; wc = (w256 - w64) * 1000 / 192
        printf "round %d: wall: window pass %.2f ms, headless sample pass %.2f ms: %.2f x;", i, ww, hw, ww / hw
        printf " cpu: %.2f ms, %.2f ms: %.2f x\n", wc, hc, wc / hc }'
done
