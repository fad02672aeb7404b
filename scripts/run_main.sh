#!/usr/bin/env bash
# The main job on the bundled data: set up the machine, build, and build a road map from the Chicago GPS traces
# with the skeleton pipeline (sampling, Rips 2-complex, geodesic function, Reeb graph, persistence
# simplification, repair, embedding), every parameter derived from the data; then score it against the
# OpenStreetMap ground truth with the graph-sampling metric. Outputs go to out/ (or OUT_DIR).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install_dependencies.sh
bash scripts/build.sh -DFEATURERECON_BUILD_TESTS=OFF -DFEATURERECON_BUILD_EXAMPLES=OFF
out=${OUT_DIR:-out}
mkdir -p "$out"
program=${BUILD_DIR:-build}/src/featurerecon
maps=test/data/chicago_maps
gzip -dc data/gps/chicago/tracks.txt.gz > "$out/chicago_tracks.txt"
"$program" skeleton --tracks "$out/chicago_tracks.txt" \
  --out-vertices "$out/chicago_map_vertices.txt" --out-edges "$out/chicago_map_edges.txt" \
  --graphml "$out/chicago_map.graphml" --geojson "$out/chicago_map.geojson" --svg "$out/chicago_map.svg" \
  > "$out/chicago_skeleton.json"
# --explain and --tracks add why samples went unmatched and how many trips drive along them.
for truth in trk25 crp; do
  "$program" evaluate-map "$maps/chicago_gt_${truth}_vertices.txt" "$maps/chicago_gt_${truth}_edges.txt" \
    "$out/chicago_map_vertices.txt" "$out/chicago_map_edges.txt" --explain --tracks "$out/chicago_tracks.txt" \
    --svg "$out/chicago_match_${truth}.png" > "$out/chicago_score_${truth}.json"
done
echo
echo "Road map of the Chicago GPS traces (889 trips, 118,360 fixes); parameters derived from the data:"
cat "$out/chicago_skeleton.json"
echo
echo "Graph-sampling score at 15 m against OSM cropped to the traces (trk25; Kharita scores F = 0.671);"
echo "trace_support: samples by trips driving along them [0, 1, 2-3, 4+] (no trip drives along 15% of trk25):"
cat "$out/chicago_score_trk25.json"
echo
echo "... and against the map-matched ground truth (crp; Kharita F = 0.740, Biagioni-Eriksson F = 0.641):"
cat "$out/chicago_score_crp.json"
echo
echo "outputs:"
for f in chicago_map_vertices.txt chicago_map_edges.txt chicago_map.graphml chicago_map.geojson chicago_map.svg \
         chicago_skeleton.json chicago_score_trk25.json chicago_score_crp.json chicago_match_trk25.png \
         chicago_match_crp.png; do
  echo "  $(realpath "$out/$f")"
done
