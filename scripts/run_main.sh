#!/usr/bin/env bash
# The main job on the bundled data: set up the machine, build, and compute the Rips 2-complex, geodesic
# function and Reeb graph of the Chicago GPS points. Outputs go to out/ (or OUT_DIR).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install_dependencies.sh
bash scripts/build.sh -DFEATURERECON_BUILD_TESTS=OFF -DFEATURERECON_BUILD_EXAMPLES=OFF
out=${OUT_DIR:-out}
mkdir -p "$out"
program=${BUILD_DIR:-build}/src/featurerecon
radius=${RADIUS:-3}
# Points of the traces (x y in UTM metres) from the bundled tracks.
gzip -dc data/gps/chicago/tracks.txt.gz | awk '!/^#/ {print $2, $3}' > "$out/chicago_points.xyz"
"$program" rips --points "$out/chicago_points.xyz" --radius "$radius" --out "$out/chicago_complex.txt"
"$program" reeb --complex "$out/chicago_complex.txt" --json > "$out/chicago_reeb.json"
echo
echo "Reeb graph of the geodesic function on the Rips complex of the Chicago GPS points (r = $radius m):"
cat "$out/chicago_reeb.json"
echo
echo "outputs:"
echo "  $(realpath "$out/chicago_points.xyz")   the input points"
echo "  $(realpath "$out/chicago_complex.txt")  the Rips 2-complex with f (exchange format)"
echo "  $(realpath "$out/chicago_reeb.json")    the Reeb graph summary"
