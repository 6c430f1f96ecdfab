#!/usr/bin/env bash
# Draws packaging/linux/touchline.png (the desktop entry's and the package's icon) with ImageMagick:
# a pitch seen from above with the ball. Run again after changing it; the PNG is committed.
set -euo pipefail
cd "$(dirname "$0")"
convert -size 256x256 xc:none -fill '#1f7a3a' -draw 'roundrectangle 8,8 247,247 40,40' \
  -fill none -stroke white -strokewidth 8 -draw 'rectangle 36,60 220,196' -draw 'line 128,60 128,196' \
  -draw 'circle 128,128 128,154' -draw 'rectangle 36,98 60,158' -draw 'rectangle 196,98 220,158' \
  -stroke none -fill '#ff9f1c' -draw 'circle 172,146 172,160' \
  -define png:bit-depth=8 touchline.png
