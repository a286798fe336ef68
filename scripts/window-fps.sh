#!/bin/sh
# Measures the window under Xvfb (docs/records/window.md): the frame rate still (full-resolution
# refinement passes) and flying (W and S held in turn), from the debug=true line the window prints
# each second; and what a still pass costs against a headless sample pass of the same size: a --bench
# frame of 16 samples per pixel, divided by 16 (a 1-sample --bench frame is cheaper than any sample
# pass: its rays go through the pixel centres, which the tracer takes a faster path for). Both in
# wall-clock time (--bench 16 before and after the window, the median of frames 9 to 16 of each) and
# in CPU time of the whole process (the window's over the last 10 of its 35 s of refinement, per pass;
# the headless one as the difference between --bench 16 and --bench 8, per sample), which a shared
# machine's load disturbs much less. The first frames and 25 s are left out: on a loaded machine the
# JIT compiler takes that long to finish with the hot loops.
# Needs xvfb-run and xdotool. (The pictures of the window in docs/ are made by scripts/window-shots.sh.)
# Usage, from anywhere after `mvn -q package -DskipTests`: scripts/window-fps.sh [WIDTH HEIGHT [SCENE]]
set -e
cd "$(dirname "$0")/.."
w=${1:-800}
h=${2:-600}
scene=${3:-scenes/bench/spec-example.yaml}
out=target/window-fps
mkdir -p "$out"
printf 'debug=true\n' > "$out/fps.properties"
bench() { # frames; prints the process's CPU seconds last
    /usr/bin/time -f 'cpu %U %S' java -jar target/glint.jar --config "$out/fps.properties" --scene "$scene" \
        --width "$w" --height "$h" --spp 16 --bench "$1" 2>&1 | grep -e '^frame' -e '^cpu'
}
bench 16 > "$out/bench.log"
bench 8 > "$out/bench8.log"
cpu() { awk '{print $14 + $15}' "/proc/$1/stat"; } # user + system, in clock ticks
xvfb-run -a -s "-screen 0 1600x1200x24" sh -c "
  java -jar target/glint.jar --config $out/fps.properties --scene $scene --width $w --height $h --spp 1024 \
      2> $out/window.log &
  pid=\$!
  sleep 25
  echo \$(awk '{print \$14 + \$15}' /proc/\$pid/stat) \$(grep -c . $out/window.log) > $out/cpu.log
  sleep 10
  echo \$(awk '{print \$14 + \$15}' /proc/\$pid/stat) \$(grep -c . $out/window.log) >> $out/cpu.log
  for i in 1 2 3; do
    xdotool keydown w; sleep 2; xdotool keyup w; xdotool keydown s; sleep 2; xdotool keyup s
  done
  xdotool key Escape; wait"
bench 16 >> "$out/bench.log" # before and after the window: the machine's load changes
median() { sort -n | awk '{a[NR] = $1} END {print a[int((NR + 1) / 2)]}'; }
still=$(grep still "$out/window.log" | tail -n +26 | sed 's/.*window \([0-9.]*\) fps.*/\1/' | median)
flying=$(grep moving "$out/window.log" | tail -n +2 | sed 's/.*window \([0-9.]*\) fps.*/\1/' | median)
size=$(grep moving "$out/window.log" | tail -n +2 | sed 's/.*ms\/frame, \([0-9x]*\) of.*/\1/' | sort | uniq -c | sort -rn \
    | head -1 | awk '{print $2}')
headless=$(grep '^frame' "$out/bench.log" | awk '$2 != "1:" {print}' | sed 's/frame \([0-9]*\): \([0-9.]*\) ms.*/\1 \2/' \
    | awk '$1 > 8 {print $2 / 16}' | median)
# the passes done between the two CPU readings: the samples count of the last debug line before each
passes() { head -n "$1" "$out/window.log" | grep still | tail -1 | sed 's/.*samples \([0-9]*\)\/.*/\1/'; }
set -- $(sed -n 1p "$out/cpu.log") $(sed -n 2p "$out/cpu.log")
window_cpu=$(awk -v c0="$1" -v c1="$3" -v p0="$(passes "$2")" -v p1="$(passes "$4")" -v hz="$(getconf CLK_TCK)" \
    'BEGIN {printf "%.1f", (c1 - c0) / hz * 1000 / (p1 - p0)}')
headless_cpu=$(awk '/^cpu/ {print ($2 + $3) * 1000}' "$out/bench.log" | head -1 \
    | awk -v eight="$(awk '/^cpu/ {print ($2 + $3) * 1000}' "$out/bench8.log")" '{printf "%.1f", ($1 - eight) / 8 / 16}')
echo "$w x $h: still $still fps, flying $flying fps (mostly at $size)"
awk -v s="$still" -v b="$headless" -v wc="$window_cpu" -v hc="$headless_cpu" 'BEGIN {
    printf "  still pass %.1f ms wall, headless sample pass %.1f ms wall: %.2f x\n", 1000 / s, b, 1000 / s / b
    printf "  still pass %.1f ms cpu, headless sample pass %.1f ms cpu: %.2f x\n", wc, hc, wc / hc }'
