#!/bin/sh
# Whether two builds render the same bytes: every shipped, bench and reference scene, Whitted's integrator
# under both shading models, written as a PFM by build A (2 threads, the config's tiles) and by build B
# twice, with 1 thread and 5 x 5 tiles and with 3 threads and 13 x 13 tiles, each compared with cmp.
# The config's min_weight (0.01 shipped) prunes by the roulette, so paths that draw numbers are checked
# too; SPP samples a pixel (default 4) number the samples of lights with a size.
# INTEGRATORS (default whitted) names the integrators to check, e.g. INTEGRATORS="whitted path bdpt";
# the path and bdpt integrators are checked under cook-torrance, the model they render with.
# Usage, from anywhere:
#   scripts/same-bytes.sh A.jar B.jar [WIDTH HEIGHT [SPP [DEPTH [CONFIG]]]]   (default 160 120 4 8 ./config.properties)
# Prints a line a difference and a summary; exits 1 when any pair differs.
set -e
a=$(realpath "$1")
b=$(realpath "$2")
cd "$(dirname "$0")/.."
w=${3:-160}
h=${4:-120}
spp=${5:-4}
depth=${6:-8}
config=${7:-config.properties}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
sed -e 's/^threads=.*/threads=1/' -e 's/^screen_divider=.*/screen_divider=5/' "$config" > "$out/one.properties"
sed -e 's/^threads=.*/threads=3/' -e 's/^screen_divider=.*/screen_divider=13/' "$config" > "$out/three.properties"
same=0
differ=0
for scene in scenes/*.yaml scenes/bench/*.yaml src/test/resources/reference/*.yaml src/test/resources/reference-pt/*.yaml; do
    for integrator in ${INTEGRATORS:-whitted}; do
        models="cook-torrance phong"
        [ "$integrator" = whitted ] || models=cook-torrance
        for model in $models; do
            flags="--scene $scene --integrator $integrator --shading $model --width $w --height $h --spp $spp --depth $depth"
            java -jar "$a" --config "$config" --threads 2 $flags --output "$out/a.pfm" > /dev/null 2>&1
            for variant in one three; do
                java -jar "$b" --config "$out/$variant.properties" $flags --output "$out/b.pfm" > /dev/null 2>&1
                if cmp -s "$out/a.pfm" "$out/b.pfm"; then
                    same=$((same + 1))
                else
                    differ=$((differ + 1))
                    echo "differ: $scene $integrator $model ($variant)"
                fi
            done
        done
    done
done
echo "same bytes: $same, differ: $differ"
[ "$differ" -eq 0 ]
