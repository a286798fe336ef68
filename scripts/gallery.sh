#!/bin/sh
# Renders the pictures of docs/gallery.md: every scene of scenes/ (not scenes/bench) at 640x360 with
# 16 samples per pixel into docs/images/gallery/NAME.png. phong-classic.yaml is shown in phong shading,
# the others in the default cook-torrance. Run from anywhere after `mvn -q package -DskipTests`.
set -e
cd "$(dirname "$0")/.."
mkdir -p docs/images/gallery
for scene in scenes/*.yaml; do
    name=$(basename "$scene" .yaml)
    shading=cook-torrance
    if [ "$name" = phong-classic ]; then
        shading=phong
    fi
    java -jar target/glint.jar --scene "$scene" --shading "$shading" --width 640 --height 360 --spp 16 \
        --output "docs/images/gallery/$name.png"
done
