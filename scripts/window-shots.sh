#!/bin/sh
# Makes every picture of the window in docs/: the window under Xvfb, driven by keys with xdotool, its
# pixels taken from an xwd dump of the screen (scripts/xwd2png.py cuts the window out):
#   docs/images/window.png          the default scene refined to the end, with the overlay
#   docs/images/window-moving.png   W held: flying at a reduced resolution
#   docs/images/window-fov.png      Z held: the field of view narrowing, shown in the overlay
#   docs/images/window-help.png     view 1, then ? : every key the window knows
#   docs/images/window-error.png    the scene saved with a typo: the last good scene stays, the error shows
#   docs/images/window-fifo.png     the scene file replaced by a FIFO: the overlay says so
# A picture of a still view is taken once the window reports (debug=true) that it has refined the view to
# the end and two dumps half a second apart are the same; a moving one once the window reports that it
# moves. Each wait lasts at most 120 s.
# Needs xvfb-run, xdotool, xwd and python3. Usage, from anywhere after `mvn -q package -DskipTests`:
#   scripts/window-shots.sh
set -e
cd "$(dirname "$0")/.."
if [ -z "$WINDOW_SHOTS_INSIDE" ]; then
    WINDOW_SHOTS_INSIDE=1 exec xvfb-run -a -s "-screen 0 1600x1200x24" "$0" "$@"
fi
out=target/window-shots
rm -rf "$out"
mkdir -p "$out" docs/images
# the shipped config, as a user's window opens, with debug on (the script reads when a view is refined)
sed 's/^debug=.*/debug=true/' config.properties > "$out/shots.properties"

# waits until the command "$@" succeeds, every 0.5 s, for at most 120 s
until_true() {
    tries=0
    until "$@"; do
        tries=$((tries + 1))
        if [ "$tries" -gt 240 ]; then echo "window-shots: gave up waiting for: $*" >&2; exit 1; fi
        sleep 0.5
    done
}
log_has() { grep -q -e "$1" "$out/window.log"; }
window_found() { id=$(xdotool search --onlyvisible --name '^Glint$' 2>/dev/null | head -1); [ -n "$id" ]; }
dump() { xwd -root -silent > "$1"; }
screen_still() { # two dumps 0.5 s apart are the same
    dump "$out/a.xwd"; sleep 0.5; dump "$out/b.xwd"; cmp -s "$out/a.xwd" "$out/b.xwd"
}
save() { # the window's pixels of the last dump to docs/images/$1.png
    python3 scripts/xwd2png.py "$out/b.xwd" "docs/images/$1.png" "$X" "$Y" "$WIDTH" "$HEIGHT"
    echo "window-shots: docs/images/$1.png"
}
open_window() { # folder scene; the window open there on the scene, its first image complete
    root=$(pwd)
    (cd "$1" && exec java -jar "$root/target/glint.jar" --config "$root/$out/shots.properties" --scene "$2" \
        2> "$root/$out/window.log") &
    pid=$!
    until_true window_found
    eval "$(xdotool getwindowgeometry --shell "$id")" # the keys go to it: the only window, it has the focus
    refined 0
}
close_window() {
    xdotool key Escape
    wait "$pid"
}
still_shot() { until_true screen_still; save "$1"; }
held_shot() { # key picture: the key held until the window says it moves, then the picture
    lines=$(grep -c . "$out/window.log" || true)
    xdotool keydown "$1"
    until_true moving_since "$lines"
    dump "$out/b.xwd"
    xdotool keyup "$1"
    save "$2"
}
moving_since() { tail -n +"$(($1 + 1))" "$out/window.log" | grep -q "moving"; }
refined_more_than() { [ "$(grep -c "window refined" "$out/window.log" || true)" -gt "$1" ]; }
refined() { # the view refined to the end for the n+1-th time, and the screen still
    until_true refined_more_than "$1"
    until_true screen_still
}

open_window . scenes/default.yaml
save window
held_shot w window-moving
refined 1
xdotool key Home
refined 2
held_shot z window-fov
refined 3
xdotool key 1
refined 4
xdotool key shift+slash
still_shot window-help
close_window

cp scenes/default.yaml "$out/scene.yaml"
open_window "$out" scene.yaml
sed -i '0,/radius: 1,/s//radus: 1,/' "$out/scene.yaml" # the first sphere's radius mistyped
until_true log_has "unknown key 'radus'"
still_shot window-error
done_so_far=$(grep -c "window refined" "$out/window.log" || true)
cp scenes/default.yaml "$out/scene.yaml" # mended: loaded and refined again
refined "$done_so_far"
rm "$out/scene.yaml"
mkfifo "$out/scene.yaml"
until_true log_has "is not a regular file"
still_shot window-fifo
close_window
rm -f "$out/scene.yaml"
