#!/bin/sh
# Renders the pictures of docs/gallery.md and README.md: every scene of scenes/ (not scenes/bench) into
# docs/images/gallery/NAME.png, at 640x360 with 16 samples per pixel unless the scene's render: block
# says otherwise (phong-classic.yaml asks for phong shading there). The gallery's settings are a config
# file, which a scene's render: block ranks above (docs/scene-format.md#render). Prints what each
# picture took and, last, the whole. Run from anywhere after `mvn -q package -DskipTests`.
set -e
cd "$(dirname "$0")/.."
mkdir -p docs/images/gallery
config=$(mktemp)
trap 'rm -f "$config"' EXIT
printf 'display_width=640\ndisplay_height=360\nsamples=16\n' >"$config"
start=$(date +%s)
count=0
for scene in scenes/*.yaml; do
    name=$(basename "$scene" .yaml)
    java -jar target/glint.jar --config "$config" --scene "$scene" --output "docs/images/gallery/$name.png"
    count=$((count + 1))
done
# the default scene again with light that bounces: the path integrator at 256 samples per pixel
java -jar target/glint.jar --config "$config" --scene scenes/default.yaml --integrator path --spp 256 \
    --output docs/images/gallery/default-path.png
count=$((count + 1))
# the lamp, its soft shadows, the frosted ball and the lens with light that bounces, at 256 samples per pixel
java -jar target/glint.jar --config "$config" --scene scenes/lamplight.yaml --integrator path --spp 256 \
    --output docs/images/gallery/lamplight-path.png
count=$((count + 1))
echo "gallery: $count pictures in $(($(date +%s) - start)) s"
