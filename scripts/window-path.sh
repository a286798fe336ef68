#!/usr/bin/env bash
# The window's pictures of the path integrator in docs/window.md: the sky-and-sun scene at rest after a
# few seconds of refinement, and while flying back (S held), with the path and with Whitted.
# Needs Xvfb, xdotool and xwd; run from the repository after `mvn -q package -DskipTests`:
#   scripts/window-path.sh            # writes docs/images/window-path-{rest,moving}.png and window-whitted-moving.png
set -euo pipefail
cd "$(dirname "$0")/.."
display=:$((90 + RANDOM % 100))
Xvfb "$display" -screen 0 1280x1024x24 >/dev/null 2>&1 &
xvfb=$!
trap 'kill $xvfb 2>/dev/null || true' EXIT
export DISPLAY=$display
sleep 1
scene=src/test/resources/reference-pt/sky-and-sun.yaml
shot() { # shot OUT.png: the window's 800x600 drawing area at the top left of the screen
  xwd -root -silent >"$1.xwd" && python3 scripts/xwd2png.py "$1.xwd" "$1" 0 0 800 600 && rm "$1.xwd"
}
window() { # window INTEGRATOR: opens the window and waits for it
  java -jar target/glint.jar --scene "$scene" --integrator "$1" >/dev/null 2>&1 &
  app=$!
  for _ in $(seq 50); do wid=$(xdotool search --name Glint 2>/dev/null | head -1) && [ -n "$wid" ] && break; sleep 0.2; done
  sleep 3
  xdotool windowfocus --sync "$wid" 2>/dev/null || true
  xdotool key h # the overlay
}
window path
sleep 8
shot docs/images/window-path-rest.png
xdotool keydown s; sleep 1.5; shot docs/images/window-path-moving.png; xdotool keyup s
kill $app; wait $app 2>/dev/null || true
window whitted
xdotool keydown s; sleep 1.5; shot docs/images/window-whitted-moving.png; xdotool keyup s
kill $app; wait $app 2>/dev/null || true
