#!/bin/sh
# Measures the window under Xvfb (docs/window.md, "Frame rate"): the frame rate still (full-resolution
# refinement passes) and flying (W and S held in turn), from the debug=true line the window prints
# each second, and a headless one-sample pass of the same size (--bench 40 before the window and after
# it, the median of the frames after the first 10 of each) to compare a still pass with.
# Needs xvfb-run and xdotool (and xwd for SHOTS=1, which also saves screenshots to docs/images/).
# Usage, from anywhere after `mvn -q package -DskipTests`: scripts/window-fps.sh [WIDTH HEIGHT [SCENE]]
set -e
cd "$(dirname "$0")/.."
w=${1:-800}
h=${2:-600}
scene=${3:-scenes/default.yaml}
out=target/window-fps
mkdir -p "$out"
printf 'debug=true\n' > "$out/fps.properties"
bench() {
    java -jar target/glint.jar --config "$out/fps.properties" --scene "$scene" --width "$w" --height "$h" \
        --spp 1 --bench 40 | grep '^frame' | tail -n +11 # the first 10 frames warm the JIT up
}
bench > "$out/bench.log"
xvfb-run -a -s "-screen 0 1600x1200x24" sh -c "
  java -jar target/glint.jar --config $out/fps.properties --scene $scene --width $w --height $h --spp 1024 \
      2> $out/window.log &
  sleep 12
  if [ -n '${SHOTS:-}' ]; then
    id=\$(xdotool search --onlyvisible --name '^Glint\$' | head -1)
    eval \$(xdotool getwindowgeometry --shell \$id)
    xwd -root -silent > $out/still.xwd
    python3 scripts/xwd2png.py $out/still.xwd docs/images/window.png \$X \$Y \$WIDTH \$HEIGHT
  fi
  for i in 1 2 3; do
    xdotool keydown w; sleep 2
    if [ -n '${SHOTS:-}' ] && [ \$i = 2 ]; then
      xwd -root -silent > $out/moving.xwd
      python3 scripts/xwd2png.py $out/moving.xwd docs/images/window-moving.png \$X \$Y \$WIDTH \$HEIGHT
    fi
    xdotool keyup w; xdotool keydown s; sleep 2; xdotool keyup s
  done
  if [ -n '${SHOTS:-}' ]; then
    xdotool key 2; sleep 1; xdotool key shift+slash; sleep 4
    xwd -root -silent > $out/help.xwd
    python3 scripts/xwd2png.py $out/help.xwd docs/images/window-help.png \$X \$Y \$WIDTH \$HEIGHT
  fi
  xdotool key Escape; wait"
bench >> "$out/bench.log" # before and after the window: the machine's load changes
median() { sort -n | awk '{a[NR] = $1} END {print a[int((NR + 1) / 2)]}'; }
still=$(grep still "$out/window.log" | tail -n +4 | sed 's/.*window \([0-9.]*\) fps.*/\1/' | median)
flying=$(grep moving "$out/window.log" | tail -n +2 | sed 's/.*window \([0-9.]*\) fps.*/\1/' | median)
size=$(grep moving "$out/window.log" | tail -n +2 | sed 's/.*ms\/frame, \([0-9x]*\) of.*/\1/' | sort | uniq -c | sort -rn \
    | head -1 | awk '{print $2}')
headless=$(sed 's/frame [0-9]*: \([0-9.]*\) ms.*/\1/' "$out/bench.log" | median)
echo "$w x $h: still $still fps, flying $flying fps (mostly at $size), headless pass $headless ms" \
    | awk -v s="$still" -v b="$headless" '{printf "%s; still pass %.1f ms = %.2f x headless\n", $0, 1000 / s, 1000 / s / b}'
