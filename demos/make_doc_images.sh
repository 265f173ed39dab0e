#!/usr/bin/env bash
# Regenerates docs/images/ with perpdot-demo's headless mode (480x320 frames).
# usage: demos/make_doc_images.sh BUILD_DIR
set -euo pipefail
demo="${1:?usage: $0 BUILD_DIR}/demos/perpdot-demo"
root="$(cd "$(dirname "$0")/.." && pwd)"
images="$root/docs/images"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
mkdir -p "$images"

# name  steps-before-the-picture  layers
shot() {
    "$demo" --headless "$1" --frames 2 --every "$2" --size 480x320 --show "$3" --no-crosscheck --out "$work/$1" > /dev/null
    cp "$work/$1/frame_0001.png" "$images/$1.png"
}
shot card_house 120 shapes
shot dominoes 100 shapes
shot tumbler 200 shapes
shot rain 110 shapes
shot offcenter_hit 80 shapes,com,velocities
shot newtons_cradle 45 shapes,velocities
shot vertical_stack 60 shapes,contacts,impulses
shot pyramid 120 shapes
shot chain 60 shapes,joints
shot suspension_bridge 150 shapes,joints
shot ragdoll 70 shapes,joints
shot windmill 200 shapes,joints
shot laser 90 shapes
shot one_way_platform 80 shapes

# a contact sheet: the dominoes falling, 16 frames a third of a second apart
"$demo" --headless dominoes --frames 16 --every 20 --size 480x320 --no-crosscheck --out "$work/sheet" > /dev/null
cp "$work/sheet/contact_sheet.png" "$images/dominoes_contact_sheet.png"
du -ch "$images"/*.png | tail -1
