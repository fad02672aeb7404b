// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
// The featurerecon command-line program: dispatches to the subcommands.

#include <FeatureRecon/version.h>

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <exception>
#include <new>
#include <string>
#include <vector>

#include "cli/cli_common.h"
#include "cli/commands.h"
#include "io/featurerecon_io.h"

namespace FeatureRecon {
namespace cli {

const std::vector<Command>& commands() {
  static const std::vector<Command> list = {
      {"rips", "Rips 2-complex of points with the geodesic function, in the exchange format",
       "usage: featurerecon rips --points FILE (--radius R | --knn K) --out COMPLEX [--search "
       "auto|kd-tree|brute-force]\n"
       "                        [--max-triangles N] [--quiet]\n"
       "\n"
       "Builds the proximity graph of the points (every pair at distance <= R, or the symmetrised K nearest\n"
       "neighbours), its Rips 2-complex (every 3-clique is a triangle) and the geodesic function: the\n"
       "shortest-path distance to a base point, the vertex farthest from an arbitrary start, in every\n"
       "connected component. Writes the complex with f = that function.\n"
       "\n"
       "  --points FILE    one point per line, whitespace-separated coordinates, any dimension; '#' "
       "comments\n"
       "  --radius R       neighbourhood radius (>= 0, inclusive)\n"
       "  --knn K          number of nearest neighbours (>= 1), symmetrised\n"
       "  --out COMPLEX    output: first line 'n m', n lines 'x y z f' (first three coordinates, "
       "zero-padded),\n"
       "                   m lines of 2 or 3 vertex indices (edges not implied by a triangle, then "
       "triangles)\n"
       "  --search S       neighbour search: auto (kd-tree up to 3D, brute force above), kd-tree, "
       "brute-force\n"
       "  --max-triangles N  refuse a complex of more than N triangles, found while counting them, before "
       "any\n"
       "                   is stored (default 134217728 = 2^27; 0: no limit)\n"
       "  --quiet          no progress on standard error\n",
       run_rips},
      {"reeb", "Reeb graph of the function of a complex file",
       "usage: featurerecon reeb --complex COMPLEX [--simplify DELTA] [--json [--persistence]] [--quiet]\n"
       "\n"
       "Computes the augmented Reeb graph of the PL function f of the complex (ties broken by vertex index)\n"
       "and reports the Reeb graph (critical nodes only).\n"
       "\n"
       "  --complex FILE   a complex in the exchange format (see 'featurerecon rips --help')\n"
       "  --simplify DELTA remove every branch and loop of persistence <= DELTA by merging (dissertation "
       "5.3);\n"
       "                   the counts then describe the simplified graph (JSON adds removed_branches,\n"
       "                   removed_loops); features above 2 DELTA survive\n"
       "  --json           print one JSON object: vertices, edges, triangles, nodes, arcs, loops (first "
       "Betti\n"
       "                   number of the Reeb graph), minima, maxima, up_forks, down_forks, components,\n"
       "                   augmented_arcs, seconds (Reeb graph time only; with --simplify, simplification "
       "included)\n"
       "  --persistence    with --json, also branch_pairs (minimum with the down-fork where its branch ends, "
       "and\n"
       "                   maximum with its up-fork) and loop_pairs (essential down-fork with the up-fork at "
       "the\n"
       "                   bottom of its thinnest loop), each a list of [birth, death] function values\n"
       "  --quiet          no progress on standard error\n",
       run_reeb},
      {"skeleton",
       "Skeleton graph of points, GPS tracks, a distance matrix or a graph (Rips, geodesic, Reeb graph, "
       "simplification, embedding)",
       "usage: featurerecon skeleton (--points FILE | --image FILE | --tracks FILE | --distance-matrix FILE "
       "|\n"
       "                              --graph FILE)\n"
       "                             [--radius R] [--delta D] [--repair DIST] [--prune H] [--sample-spacing "
       "S]\n"
       "                             [--ink dark|bright] [--ink-threshold T]\n"
       "                             [--link-gap G] [--heading-tolerance A] [--undirected] [--min-density "
       "F]\n"
       "                             [--min-lateral-density LD] [--density-radius DR]\n"
       "                             [--density-heading-tolerance DA] [--first-point-positions]\n"
       "                             [--segment-support SS] [--segment-turn-tolerance ST] "
       "[--straight-confirmed SC]\n"
       "                             [--quiet-ends Q] [--local-support K] [--min-local-support FL] [--merge "
       "MD]\n"
       "                             [--branch-merge BM] [--level-width W]\n"
       "                             [--smoothing N] [--smoothing-method M] [--max-gap G] [--max-triangles "
       "N]\n"
       "                             --out-vertices V --out-edges E\n"
       "                             [--lonlat] [--graphml F] [--geojson F] [--ply F] [--svg F "
       "[--picture-size P]]\n"
       "                             [--quiet]\n"
       "\n"
       "Rips 2-complex at radius R, geodesic function, Reeb graph, removal of features of persistence <= D,\n"
       "optional repair of gaps up to DIST then a second simplification, removal of components of height <= "
       "H,\n"
       "embedding (for tracks, then lines closer than MD merged into one); writes the skeleton as a road "
       "map\n"
       "(V: 'id,x,y', E: 'id,v1,v2'; arcs as polylines) and prints a JSON summary with every parameter "
       "used.\n"
       "\n"
       "Input (exactly one):\n"
       "  --points FILE    one point per line (any dimension; the map and picture get the first two "
       "coordinates,\n"
       "                   above 3-D those of the PCA projection). Without --radius, R is derived from the\n"
       "                   points: 1.5 times the scale at which they look one-dimensional (the mean number "
       "of\n"
       "                   neighbours within r, measured from 1,000 points against all, grows as r to the\n"
       "                   intrinsic dimension plus at most 0.5, and is at least 8), or more where the "
       "points are\n"
       "                   too sparse for it to bridge their random gaps (gap radius G); D defaults to the "
       "larger\n"
       "                   of R and 2.25 times that scale, and S to 0 while a point has at most 32 "
       "neighbours\n"
       "                   within R on average, else to the spacing that leaves about 32, at most (R - G)/2 "
       "unless\n"
       "                   the complex would still be large (a warning says so); the JSON summary prints "
       "the\n"
       "                   estimate\n"
       "  --image FILE     the ink of a picture (PNG, JPEG, PGM, PPM; colour is read as its luma): every "
       "pixel\n"
       "                   darker than T (--ink dark, the default) or at least T (--ink bright; T = "
       "--ink-threshold,\n"
       "                   default 128) is a point at its centre, x = column + 0.5, y = height - row - 0.5 "
       "(y up,\n"
       "                   in pixels). R defaults to 1.5 (the 8 neighbours of a pixel) and D to 2R\n"
       "  --tracks FILE    GPS tracks, lines 'trip_id x y t' (metres, seconds), or a directory with one trip "
       "per\n"
       "                   '*.txt' file of lines 'x y [t]' (the map-construction benchmark's "
       "trips/trip_N.txt; trips\n"
       "                   in the natural order of the names, trip_2 before trip_10). Each trip is sorted by "
       "time, its\n"
       "                   segments up to the link gap are densified where the traces confirm them, the "
       "result is\n"
       "                   sampled at spacing S (greedy, per direction), consecutive samples of a trip are "
       "graph\n"
       "                   edges, and sparse samples are dropped. Unset values derive from the median step "
       "M\n"
       "                   between fixes: R = M (clamped to [10, 30]), S = R/2, G = max(4M, 2R), SS = "
       "max(20, 2R/3),\n"
       "                   ST = 30, D = 3R, DIST = 2.5R, H = 5R, A = 30, F = 0.05, LD = 0.3, DR = 2R, DA = "
       "45,\n"
       "                   MD = 8\n"
       "  --lonlat         with --tracks: x and y are longitude and latitude in degrees (WGS84). The fixes "
       "are\n"
       "                   projected to metres (transverse Mercator centred on them, scale 1 on its central\n"
       "                   meridian; at most 500 km east or west of it), lengths above stay in metres, and "
       "the\n"
       "                   map, GraphML, GeoJSON and PLY are written in degrees (the picture in metres; "
       "GeoJSON\n"
       "                   lines that cross the antimeridian are cut there into MultiLineStrings).\n"
       "                   Tracks that look like degrees (fixes under 1 cm apart, all within +-180, +-90) "
       "are\n"
       "                   refused without it\n"
       "  --distance-matrix FILE  n lines of n distances (symmetric, zero diagonal); embedded by classical "
       "MDS\n"
       "                   (top three eigenpairs by block Lanczos; dense up to 300 points). Without "
       "--radius, R is\n"
       "                   derived from the distances as for points\n"
       "  --graph FILE     a graph in the complex exchange format ('n m', n lines 'x y z f' (f unused), m "
       "lines of\n"
       "                   2 or 3 vertex indices; a triangle line gives its three edges); edge lengths are "
       "Euclidean;\n"
       "                   no --radius. As for points, the complex is the graph's flag complex (every "
       "3-cycle of\n"
       "                   edges a triangle)\n"
       "\n"
       "Options:\n"
       "  --radius R       Rips radius in input units (default: estimated, see --points; 1.5 for --image; "
       "for --tracks\n"
       "                   from the median step); not with --graph\n"
       "  --delta D        persistence threshold (default R, or the estimate's when R is derived (see "
       "--points);\n"
       "                   2R for images, 3R for tracks; 0 with --graph, which has no radius: give D to "
       "simplify)\n"
       "  --repair DIST    join degree-1 nodes at most DIST apart, then simplify again (default 0; 2.5R for "
       "tracks)\n"
       "  --prune H        remove components of height <= H (default 0; 5R for tracks)\n"
       "  --sample-spacing S  thin the points first: keep a point when no kept point is closer than S (0: "
       "no\n"
       "                   thinning; default 0, see --points without --radius; with --tracks S > 0, unset\n"
       "                   is automatic, S = R/2)\n"
       "  --link-gap G     link consecutive fixes at most G apart (unset: automatic; 0: no linking)\n"
       "  --segment-support SS  densify a segment between fixes only where the traces confirm it: every\n"
       "                   inserted point within SS of some fix, or the trip does not turn there (it arrives "
       "and\n"
       "                   leaves within ST degrees of the segment, each direction over at least SS). "
       "Between\n"
       "                   sparse fixes a turning vehicle cuts the corner across a block where no fix lies. "
       "An\n"
       "                   unconfirmed segment up to 4 SS links its ends only, a longer one breaks the "
       "trip.\n"
       "                   When fewer than 20 % of the checked segments (within the link gap, longer than 2 "
       "SS)\n"
       "                   are confirmed by fixes, the traces are too sparse to tell and all are used. 0: no "
       "check\n"
       "  --segment-turn-tolerance ST  see --segment-support (degrees, default 30)\n"
       "  --straight-confirmed SC  the turn rule of --segment-support applies only where the traces show it "
       "tells\n"
       "                   streets: of the checked segments a trip drives straight through, at least SC must "
       "be\n"
       "                   confirmed by fixes (95 % upper confidence bound; default 0.75; 0: always "
       "applies).\n"
       "                   Random routes sampled hundreds of metres apart run straight while their segments "
       "cut\n"
       "                   blocks: there straight segments are confirmed no more often than the others\n"
       "  --quiet-ends Q   where the turn rule does not apply, an unconfirmed straight segment is still used "
       "when\n"
       "                   fewer than Q distinct fix positions (its own counted) lie within SS of each end: "
       "no\n"
       "                   other trip could have confirmed it (a street one trip drives). Default 4; 0: off\n"
       "  --local-support K  a segment longer than 4 SS is confirmed at a local distance instead of SS: from "
       "each\n"
       "                   end, the distance to the K-th nearest distinct fix position (its own counted), "
       "the\n"
       "                   larger of the two, at least FL x SS (--min-local-support, default 0.6). Where "
       "fixes lie\n"
       "                   densely a chord across a block still passes within SS of fixes on the streets "
       "around\n"
       "                   it; on a street they lie about that far apart. Default 8; 0: SS everywhere\n"
       "  --heading-tolerance A  Rips edges only between samples whose driving directions differ by <= A "
       "degrees\n"
       "  --undirected     compare directions modulo 180 degrees (both ways of a street together)\n"
       "  --first-point-positions  a sample stays at the first trace point that created it (default: it "
       "moves to\n"
       "                   the mean of the fixes that joined it)\n"
       "  --min-density F  drop samples standing for fewer fixes than F times the most within DR travelling "
       "within\n"
       "                   DA degrees of the same direction (a quiet carriageway beside a busy one stays)\n"
       "  --density-radius DR  the neighbourhood of --min-density and --min-lateral-density (metres; default "
       "2R)\n"
       "  --density-heading-tolerance DA  see --min-density (degrees, in [0, 180]; default 45)\n"
       "  --min-local-support FL  see --local-support (a fraction of SS; default 0.6)\n"
       "  --min-lateral-density LD  also drop samples standing for fewer than LD times the most of those "
       "beside\n"
       "                   them (offset at least 45 degrees off their direction): scatter beside the band of "
       "its\n"
       "                   street. A street that continues or crosses a busy one stays; one forking off it "
       "at\n"
       "                   under DA degrees loses its first metres. Samples of parked vehicles (no "
       "direction) are\n"
       "                   neither judged nor counted. 0: off\n"
       "  --merge MD       last stage for tracks: parts of the map closer than MD metres become one line "
       "(the two\n"
       "                   directions of a two-way street; a divided road's carriageways lie further apart); "
       "0: off.\n"
       "                   The merged lines are drawn with 20 Laplacian rounds, automatic W and G "
       "(merge_smoothing,\n"
       "                   merge_smoothing_rounds, merge_level_width and merge_max_gap in the JSON); "
       "--level-width,\n"
       "                   --smoothing, --smoothing-method and --max-gap then draw the skeleton before the "
       "merge\n"
       "  --branch-merge BM  branch nodes (degree >= 3) joined by an arc at most BM long become one node, a "
       "cluster\n"
       "                   at most BM across: where curves cross or touch, the Reeb graph draws two forks a "
       "little\n"
       "                   apart (default: 2 W; 0: off; with --tracks default 0)\n"
       "  --level-width W  level-set slab width of the embedding (default: median edge length)\n"
       "  --smoothing N    smoothing rounds of each arc, ends fixed, at most 10^6 (default 10; 2 with "
       "--tracks)\n"
       "  --smoothing-method M  taubin (default: each round a step towards the neighbours' mean and one "
       "back,\n"
       "                   which keeps the shape of coarse arcs) or laplacian (the step towards only: "
       "shrinks,\n"
       "                   pulling an arc of few pieces onto the chord between its ends; default with "
       "--tracks,\n"
       "                   where it scored higher)\n"
       "  --max-gap G      an arc whose polyline jumps farther than G follows the graph's shortest path "
       "there\n"
       "                   (unset: twice the median edge length; 0: straight segments)\n"
       "  --max-triangles N  refuse a Rips complex of more than N triangles, found while counting them (a "
       "radius\n"
       "                   too large for the data; the pipeline needs about 40 bytes a triangle); default\n"
       "                   134217728 = 2^27; 0: only the Reeb graph's limit, 2^31 - 1 edges and triangles\n"
       "  --graphml, --geojson, --ply, --svg   also write GraphML, GeoJSON (2D), PLY polylines (3D), a "
       "picture\n"
       "                   (--svg F.svg, or F.png, .jpg, .pgm, .ppm: the same drawing rasterised): the "
       "points grey,\n"
       "                   arcs coloured, nodes black; 3 pixels per radius (with --graph, per level width "
       "W), the\n"
       "                   drawing's longer side kept within 1000 to 4000 pixels, inside a margin of 10 "
       "pixels. Dots\n"
       "                   are a fifth of the radius drawn (at most 1 pixel), arcs and nodes half of it (at "
       "most 2\n"
       "                   and 3). A raster takes about 15 bytes a pixel (240 MB at 4000 x 4000)\n"
       "  --picture-size P  the drawing's longer side in pixels instead, in [100, 8192] (the margin adds "
       "20)\n",
       run_skeleton},
      {"evaluate-map", "Compare a reconstructed road map with a ground truth (graph-sampling metric)",
       "usage: featurerecon evaluate-map GT_VERTICES GT_EDGES REC_VERTICES REC_EDGES [--threshold 15] "
       "[--interval 5]\n"
       "                                 [--bearing 45] [--crop-to-tracks TRACKS [--crop-radius 25] "
       "[--crop-gap 500]]\n"
       "                                 [--samples-out CSV] [--svg PICTURE] [--explain] [--tracks TRACKS] "
       "[--lonlat]\n"
       "                                 [--matching greedy|optimal] [--quiet]\n"
       "\n"
       "Samples both maps every INTERVAL metres (per component, breadth-first from the point at half its "
       "edge\n"
       "length), matches ground-truth samples to reconstruction samples at most THRESHOLD metres away whose\n"
       "direction-insensitive bearings differ by less than BEARING degrees (greedy over the 10 nearest), "
       "and\n"
       "prints JSON: precision, recall, f_score (null over no samples) and the counts. Bearing differences "
       "lie\n"
       "in [0, 90]: a BEARING above 90 ignores bearings, 90 still refuses perpendicular samples.\n"
       "\n"
       "  GT_*, REC_*      vertex files 'id,x,y' and edge files 'id,v1,v2[,flag]' (metres, or degrees with "
       "--lonlat;\n"
       "                   edges undirected; ids are integers, each once per file)\n"
       "  --crop-to-tracks keep only ground-truth edges whose 5 m samples all lie within --crop-radius "
       "(default 25 m)\n"
       "                   of a trace point of TRACKS (lines 'trip_id x y t', or a directory of one-trip\n"
       "                   files 'x y t' as for skeleton --tracks): the fixes, and points every 10 m "
       "between\n"
       "                   consecutive fixes of a trip (by time) at most --crop-gap apart (default 500 m; "
       "0:\n"
       "                   the fixes alone). The crop of the Chicago reference ground truth trk25\n"
       "  --samples-out    write every sample: 'map,index,x,y,bearing,partner' (partner -1: unmatched)\n"
       "  --svg            picture of the match: truth green (matched) or red (missed), reconstruction blue\n"
       "                   (matched) or orange (spurious); SVG, or PNG, JPEG, PGM, PPM by the extension\n"
       "  --explain        add why samples went unmatched, for the truth ('missed') and the reconstruction\n"
       "                   ('spurious'): 'taken' (an aligned sample lies within THRESHOLD, but it went to\n"
       "                   another: mostly a parallel line in one map only), 'offset' (nearest aligned one\n"
       "                   1-2 THRESHOLD away), 'crossing' (only non-aligned samples within 2 THRESHOLD),\n"
       "                   'absent' (nothing there)\n"
       "  --tracks         the GPS trips the reconstruction came from (as for --crop-to-tracks): add\n"
       "                   'trace_support', the samples split by how many trips drive along them (a segment\n"
       "                   within THRESHOLD, bearing within BEARING) into lists [0, 1, 2-3, 4+ trips] for "
       "the\n"
       "                   truth, the missed and the spurious samples, and the recall within the driven "
       "truth\n"
       "  --lonlat         every file gives longitude and latitude in degrees (WGS84): all are projected to\n"
       "                   metres with one transverse Mercator centred on them (as skeleton --lonlat), so "
       "that\n"
       "                   THRESHOLD, INTERVAL and the crop radius stay metres; --samples-out in degrees\n"
       "  --matching       greedy (default): pairs accepted by increasing distance, each ground-truth "
       "sample\n"
       "                   choosing among its 10 nearest (the GraphSamplingToolkit's matching); optimal: a\n"
       "                   maximum-weight bipartite matching over all admissible pairs, weight THRESHOLD -\n"
       "                   distance (at least the greedy weight; on the Chicago maps 0.1-0.7 % more pairs)\n"
       "  --quiet          no progress on standard error\n",
       run_evaluate_map},
      {"synthetic-city", "Simulate GPS trips in a city whose streets are known (test data for road maps)",
       "usage: featurerecon synthetic-city --out-tracks TRACKS --out-vertices V --out-edges E\n"
       "                                   [--layout grid|organic] [--columns 8] [--rows 6] [--block-width "
       "120]\n"
       "                                   [--block-height 90] [--rotation 0] [--jitter 10] [--missing 0.1]\n"
       "                                   [--curvature 0] [--trips 300] [--speed 10] [--interval 3.6] "
       "[--noise 4]\n"
       "                                   [--bias 2] [--lane-offset 2] [--seed 1]\n"
       "                                   [--out-streets-vertices SV --out-streets-edges SE] [--quiet]\n"
       "\n"
       "Lays out a street network and drives trips on it: shortest routes between random intersections, on "
       "the\n"
       "right-hand side, recorded every INTERVAL seconds with Gaussian noise and a constant bias per trip.\n"
       "Deterministic for a seed. Writes the trips (lines 'trip_id x y t') and the streets that were driven "
       "(the\n"
       "ground truth for evaluate-map, 'id,x,y' and 'id,v1,v2'); prints a JSON summary.\n"
       "\n"
       "  --layout         grid: a columns x rows grid of blocks, jittered, with a diagonal avenue "
       "(default);\n"
       "                   organic: columns x rows random intersections in the same rectangle, joined by "
       "the\n"
       "                   streets of their Gabriel graph (junctions of any degree and angle)\n"
       "  --columns, --rows  intersections across and along (each at least 2, at most 2^24 together; "
       "default 8, 6)\n"
       "  --block-width, --block-height  the blocks' size (m; default 120, 90)\n"
       "  --rotation       the grid's angle (degrees; default 0)\n"
       "  --jitter         grid: each intersection moves up to this far in x and in y (m; at most w h /\n"
       "                   (2 (w + h)) of the block sides, 25.7 m for the default blocks, so that the\n"
       "                   diagonal avenue crosses no street; default 10, or that limit for smaller\n"
       "                   blocks)\n"
       "  --missing        fraction of streets removed, keeping the network connected (default 0.1)\n"
       "  --curvature C    bend every street: its middle lies up to C x its length off the chord, in [0, "
       "0.5]\n"
       "  --trips N        number of trips, at most 2^26 (67,108,864)\n"
       "  --speed          mean speed (m/s); each trip drives at 0.7 to 1.3 times it\n"
       "  --interval       seconds between the fixes of a trip (default 3.6)\n"
       "  --noise, --bias  standard deviation of each fix's noise and of each trip's offset, per coordinate "
       "(m)\n"
       "  --lane-offset    vehicles drive this far right of the centre line (m; at most half the shorter\n"
       "                   block side; default 2, or a quarter of the shorter side for blocks under 8 m)\n"
       "  --seed N         the same seed gives the same city and trips (default 1)\n"
       "  --out-tracks, --out-vertices, --out-edges  the trips and the driven streets (required)\n"
       "  --out-streets-*  also write every street, driven or not\n"
       "  --quiet          no progress on standard error\n"
       "\n"
       "example: featurerecon synthetic-city --layout organic --curvature 0.15 --trips 600 --out-tracks "
       "t.txt\n"
       "           --out-vertices gt_v.txt --out-edges gt_e.txt\n"
       "         featurerecon skeleton --tracks t.txt --out-vertices v.txt --out-edges e.txt\n"
       "         featurerecon evaluate-map gt_v.txt gt_e.txt v.txt e.txt --explain --tracks t.txt\n",
       run_synthetic_city},
      {"sample", "Feature-aware downsampling of a point cloud (bilateral blue noise on points with normals)",
       "usage: featurerecon sample --input FILE [--count M] [--radius R] [--method elimination|darts]\n"
       "                           [--sigma-position S] [--sigma-feature S] [--unoriented] [--periodic]\n"
       "                           [--seed N] [--normal-neighbors K] --out FILE [--quiet]\n"
       "\n"
       "Keeps a subset of the points (positions, normals where the input has them or they are estimated, "
       "and\n"
       "PLY colours; other attributes are not written) with blue-noise spacing in the\n"
       "bilateral distance xi = sqrt(|dp|^2 / S_p^2 + |dn|^2 / S_f^2) of positions and unit normals, so "
       "creases\n"
       "and both sides of thin walls keep their samples. Without --sigma-feature the spacing is Euclidean.\n"
       "Points in the plane (a text file of lines 'x y') are sampled with Euclidean spacing and written as\n"
       "such lines. Prints JSON: points, kept, radius, relative_radius (rho on the input's surface or "
       "volume,\n"
       "area or torus; null when undefined: the kept points are fewer than two, or all on one line or plane\n"
       "of a volume), seconds.\n"
       "\n"
       "  --input FILE        PLY, OFF (vertices; NOFF with normals) or XYZ (x y z [nx ny nz]), or another\n"
       "                      text file of 'x y' (points in the plane) or 'x y z [nx ny nz]'; normals are\n"
       "                      estimated (jet fitting, MST orientation, K neighbours) when absent and "
       "needed;\n"
       "                      PLY colours are the vertex properties red, green, blue (uchar)\n"
       "  --count M           exact number of points to keep (elimination), or the target of the dart "
       "radius;\n"
       "                      with darts and --radius R, a cap: the first M kept in the seeded visiting "
       "order\n"
       "  --radius R          elimination: r_max (default from the area or volume); darts: the conflict "
       "radius\n"
       "  --method M          elimination (weighted sample elimination, exact count; default; needs M) or "
       "darts\n"
       "                      (maximal bilateral dart throwing at R, or at the radius giving M points; needs "
       "R\n"
       "                      or M or both)\n"
       "  --sigma-position S  spatial scale of the bilateral distance (default 1)\n"
       "  --sigma-feature S   normal scale (unit normals: |dn|^2 in [0, 4]); default infinity (Euclidean; "
       "'inf')\n"
       "  --unoriented        compare normals up to sign (default: oriented, opposite sides are far apart);\n"
       "                      with --sigma-feature\n"
       "  --normal-neighbors K  neighbours of the normal estimate (jet fitting, MST orientation) when "
       "normals "
       "are\n"
       "                      estimated (with --sigma-feature, for a file without normals); in [3, 10^6], "
       "default 18\n"
       "  --periodic          positions modulo 1, distances of the unit torus: a set that tiles the plane "
       "or\n"
       "                      space (the domain is the torus, measure 1; `sample-stats --periodic` takes "
       "its\n"
       "                      spectrum); the kept points are written as given\n"
       "  --seed N            ties and visiting order; the same seed gives the same output (default 0)\n"
       "  --out FILE          PLY, OFF or XYZ by extension, with normals when there are any; colours in PLY\n"
       "                      only (the JSON says \"colors\": \"file\", \"none\" or \"dropped\"); .txt for\n"
       "                      points in the plane\n"
       "  --quiet             no progress on standard error\n"
       "\n"
       "example: featurerecon sample --input fandisk.ply --count 10000 --sigma-feature 0.5 --out s.ply\n"
       "         featurerecon sample --input candidates.txt --count 1000 --periodic --out tile.txt\n"
       "         featurerecon sample-stats --input tile.txt --periodic --spectrum spectrum.csv\n",
       run_sample},
      {"sample-stats", "Spacing statistics of a sample set (relative radius, average minimum distance)",
       "usage: featurerecon sample-stats --input FILE [--domain-measure A] [--intrinsic-dimension 2|3]\n"
       "                                 [--periodic [--spectrum CSV] [--max-frequency F] [--spectrum-method "
       "M]]\n"
       "                                 [--sigma-position S] [--sigma-feature S] [--quiet]\n"
       "\n"
       "Prints JSON: samples, hexagonal_distance d_hex (nearest distance of the densest packing of the "
       "samples:\n"
       "hexagonal in 2D, FCC in 3D), minimum_distance, relative_radius rho = d_min / d_hex and\n"
       "average_minimum_distance (mean nearest-neighbour distance / d_hex; about 0.466 for white noise); "
       "these\n"
       "four are null and degenerate is true for fewer than two samples, a domain of measure 0 or samples\n"
       "on one line (or plane, in a volume).\n"
       "\n"
       "  --input FILE             PLY, OFF or XYZ point cloud (x y z [nx ny nz]), as `sample` reads it, or\n"
       "                           another text file of 2D or 3D points (x y [z])\n"
       "  --domain-measure A       area or volume of the domain (default: for clouds the estimated surface "
       "area\n"
       "                           or the bounding volume, by the intrinsic dimension; bounding box for "
       "text\n"
       "                           points (surface area for 3D points with --intrinsic-dimension 2); 1 with\n"
       "                           --periodic)\n"
       "  --intrinsic-dimension D  2 (surfaces, images) or 3 (volumes); default: estimated for clouds (flat\n"
       "                           neighbourhoods; also with --domain-measure; 3 with --periodic), the\n"
       "                           number of coordinates for text points\n"
       "  --periodic               distances on the unit torus (positions modulo 1); for 2D samples also "
       "the\n"
       "                           effective Nyquist frequency and the oscillation of Heck, Schloemer and "
       "Deussen\n"
       "                           (frequencies in units of sqrt(N)/2: a square lattice has nu_eff = 1)\n"
       "  --max-frequency F        with --periodic: periodogram up to |f_x|, |f_y| <= F (default 6 sqrt(N), "
       "which\n"
       "                           holds the oscillation band; at most 16384); about 2 s for 10^5 samples "
       "at\n"
       "                           the default (a non-uniform FFT)\n"
       "  --spectrum-method M      with --periodic: automatic (default), gridded (the non-uniform FFT, to\n"
       "                           about 2e-11 N) or direct (every exponential summed, O(N F^2) time)\n"
       "  --spectrum CSV           with --periodic: write frequency, radial_power, anisotropy_db per "
       "annulus\n"
       "  --sigma-position S       spatial scale of the bilateral distance (default 1)\n"
       "  --sigma-feature S        bilateral distances with the normals of a cloud (default: Euclidean)\n"
       "  --quiet                  no progress on standard error\n",
       run_sample_stats},
      {"sample-image", "Feature-aware blue-noise sampling of a picture (pixels or the continuous image)",
       "usage: featurerecon sample-image --input IMAGE [--count M] [--radius R]\n"
       "                                 [--method elimination|darts|continuous] [--sigma-feature S] "
       "[--grey]\n"
       "                                 [--seed N] [--out FILE] [--svg FILE] [--picture FILE] [--mosaic "
       "FILE]\n"
       "                                 [--quiet]\n"
       "\n"
       "Blue-noise samples of an image in the bilateral distance xi = sqrt(|dp|^2 + |dc|^2 / S^2) of "
       "positions\n"
       "(pixels) and colours (mean squared channel difference, channels in [0, 1]): with --sigma-feature "
       "the\n"
       "samples crowd along edges and thin lines; without it the spacing is uniform. Prints JSON: samples,\n"
       "radius, relative_radius (rho on the image rectangle; null when undefined: fewer than two samples or "
       "all\n"
       "on one line), seconds.\n"
       "\n"
       "  --input IMAGE      PNG, JPEG, PGM or PPM (grey or RGB)\n"
       "  --method M         elimination (weighted sample elimination of pixels, exact count; default; needs "
       "M),\n"
       "                     darts (maximal dart throwing over the pixels at R, or at the radius giving M\n"
       "                     samples; needs R or M or both) or\n"
       "                     continuous (darts anywhere in the image rectangle, colours interpolated "
       "bilinearly;\n"
       "                     needs R, M caps the count; a radius that lets more than 2^27 samples into\n"
       "                     the picture needs M)\n"
       "  --count M          number of samples (with darts and --radius R, a cap: the first M kept in the "
       "seeded\n"
       "                     visiting order)\n"
       "  --radius R         conflict radius in pixels (darts, continuous); r_max for elimination\n"
       "  --sigma-feature S  colour scale (colour distances lie in [0, 1]); default infinity (Euclidean)\n"
       "  --grey             sample the luma of a colour image\n"
       "  --seed N           the same seed gives the same samples (default 0)\n"
       "  --out FILE         samples as text: 'x y value' or 'x y r g b' (pixels; channels in [0, 1]); .csv\n"
       "                     adds a header and commas\n"
       "  --svg FILE         the samples as dots of their colour\n"
       "  --picture FILE     the same as a PNG, JPEG, PGM or PPM of the input's size\n"
       "  --mosaic FILE      every pixel in the colour of its nearest sample (a Voronoi mosaic; PNG, JPEG, "
       "PGM\n"
       "                     or PPM); the JSON then has mosaic_psnr_db against the input\n"
       "  --quiet            no progress on standard error\n",
       run_sample_image},
      {"stipple", "Stippling: dots following a picture's darkness, coloured from a small palette",
       "usage: featurerecon stipple IMAGE --count N [--method lloyd|bilateral-lloyd|darts|kernel]\n"
       "                           [--sigma-feature S] [--iterations K] [--palette C] [--gamma G] [--grey]\n"
       "                           [--seed N] [--out FILE.svg] [--png FILE.png] (one or both) [--quiet]\n"
       "\n"
       "N dots whose density follows the darkness (1 - luma)^G of the picture, each in the palette colour "
       "nearest\n"
       "to the pixel under it. Prints JSON: dots, iterations, stop, dot_radius, seconds.\n"
       "\n"
       "  IMAGE              PNG, JPEG, PGM or PPM (grey or RGB)\n"
       "  --method M         lloyd: Euclidean adaptive Lloyd (exact Voronoi cells of CGAL's Delaunay\n"
       "                     triangulation, density integrated per pixel; the reference; default);\n"
       "                     bilateral-lloyd: discrete Lloyd on the pixels in the bilateral distance, the\n"
       "                     colour as the feature (dots keep to their side of an edge); darts: bilateral "
       "dart\n"
       "                     throwing with radii following the density; kernel: darts relaxed by the "
       "bilateral\n"
       "                     Gaussian kernel energy\n"
       "  --count N          number of dots, at most the number of pixels with any darkness\n"
       "  --sigma-feature S  colour scale of the bilateral methods, positions in units of the mean dot "
       "spacing\n"
       "                     (colour distances lie in [0, 1]; smaller keeps edges sharper); default 0.3\n"
       "  --iterations K     Lloyd iterations (default 50) or kernel steps (default 100), at most 10^6\n"
       "  --palette C        colours of an RGB picture's dots: k-means of its colours (default 6; grey: "
       "black)\n"
       "  --gamma G          density exponent (default 1; larger leaves light areas emptier)\n"
       "  --grey             stipple the luma of a colour picture in black\n"
       "  --seed N           the same seed gives the same dots (default 0)\n"
       "  --out FILE.svg     the dots as an SVG picture on white\n"
       "  --png FILE.png     the same as a PNG (or JPEG, PGM, PPM) of the input's size\n"
       "  --quiet            no progress on standard error\n",
       run_stipple},
      {"bilateral-filter",
       "Bilateral filter of a picture on sampled taps, with PSNR and SSIM against the exact one",
       "usage: featurerecon bilateral-filter IMAGE [--sampling uniform|bilateral|exact] [--mode "
       "local|global]\n"
       "                                    [--budget B] [--sigma-spatial S] [--sigma-range S] [--radius R]\n"
       "                                    [--sampling-sigma S] [--no-compensation] [--candidates C] "
       "[--grey]\n"
       "                                    [--seed N] --out FILE.png [--exact-out FILE.png] [--quiet]\n"
       "\n"
       "The bilateral filter (spatial Gaussian S over a (2R+1)^2 window, range Gaussian on colours in [0, "
       "1])\n"
       "evaluated on blue-noise taps, each reading the pixel it falls in. Prints JSON: "
       "taps_per_kernel_pixel,\n"
       "sampling_radius, psnr_db and ssim against the exact filter (psnr_db null when equal), seconds of "
       "the\n"
       "sampled filter and exact_seconds of the exact one.\n"
       "\n"
       "  IMAGE              PNG, JPEG, PGM or PPM (grey or RGB)\n"
       "  --sampling M       uniform: Euclidean Poisson-disk taps; bilateral: Poisson-disk in the bilateral\n"
       "                     distance with the colour as the feature (taps crowd at edges, both sides "
       "sampled;\n"
       "                     default); exact: every pixel of the window (the taps' options --mode, "
       "--budget,\n"
       "                     --sampling-sigma, --no-compensation, --candidates and --seed do not apply)\n"
       "  --mode M           global: one pattern for the picture, each pixel uses the taps in its window\n"
       "                     (default); local: a pattern per pixel, drawn in its window\n"
       "  --budget B         taps per kernel pixel, in (0, 16] (default 0.5)\n"
       "  --sigma-spatial S  spatial sigma in pixels (default 3)\n"
       "  --sigma-range S    range sigma on colours in [0, 1] (default 0.1)\n"
       "  --radius R         window half-width in pixels (default ceil(2 sigma-spatial))\n"
       "  --sampling-sigma S colour scale of the bilateral sampling distance (default: the range sigma;\n"
       "                     bilateral sampling only)\n"
       "  --no-compensation  do not weight bilateral taps by their inverse density (bilateral sampling "
       "only)\n"
       "  --candidates C     candidate darts per tap, 2 to 64 (default 4)\n"
       "  --grey             filter the luma of a colour picture\n"
       "  --seed N           the same seed gives the same taps (default 0)\n"
       "  --out FILE         the sampled filter's picture (PNG, JPEG, PGM or PPM)\n"
       "  --exact-out FILE   the exact filter's picture\n"
       "  --quiet            no progress on standard error\n",
       run_bilateral_filter},
  };
  return list;
}

}  // namespace cli
}  // namespace FeatureRecon

namespace {
void print_main_help(std::FILE* out) {
  std::fprintf(out, "featurerecon %s: feature-aware sampling and reconstruction\n\n",
               FEATURERECON_VERSION_STRING);
  std::fprintf(
      out,
      "usage: featurerecon COMMAND [OPTIONS]   (featurerecon COMMAND --help for its options)\n\ncommands:\n");
  for (const auto& c : FeatureRecon::cli::commands()) std::fprintf(out, "  %-17s %s\n", c.name, c.summary);
}
}  // namespace

namespace {
/// Interrupted (Ctrl-C, kill, a closed terminal): the temporaries go, then the signal does what it would
/// have.
extern "C" void remove_temporaries_and_stop(int signal) {
  FeatureRecon::io::remove_temporaries_now();
  std::signal(signal, SIG_DFL);
  std::raise(signal);
}
}  // namespace

namespace {
/// The exit code once standard output is flushed: what it carries (a summary, help) is a result too, and a
/// full disk or a closed pipe must not pass for success.
int flushed(const char* who, int code) {
  if (std::fflush(stdout) == 0 && !std::ferror(stdout)) return code;
  const int error = errno;
  std::fprintf(stderr, "%s: error: writing standard output failed: %s\n", who, std::strerror(error));
  return code == 0 ? 1 : code;
}
}  // namespace

int main(int argc, char** argv) {
  using namespace FeatureRecon::cli;
  for (const int s : {SIGINT, SIGTERM, SIGHUP})
    if (std::signal(s, remove_temporaries_and_stop) == SIG_IGN)
      std::signal(s, SIG_IGN);  // keep nohup's choice
  if (argc < 2) {               // a usage error: the help goes where errors go
    print_main_help(stderr);
    return 2;
  }
  const std::string name = argv[1];
  if (name == "--help" || name == "-h" || name == "help") {
    print_main_help(stdout);
    return flushed("featurerecon", 0);
  }
  if (name == "--version") {
    std::printf("featurerecon %s\n", FEATURERECON_VERSION_STRING);
    return flushed("featurerecon", 0);
  }
  for (const Command& c : commands()) {
    if (name != c.name) continue;
    std::vector<std::string> args(argv + 2, argv + argc);
    for (const std::string& a : args)
      if (a == "--help" || a == "-h") {
        std::fputs(c.help, stdout);
        return flushed(("featurerecon " + name).c_str(), 0);
      }
    try {
      const int code = c.run(args);
      return flushed(("featurerecon " + name).c_str(), code);
    } catch (const Usage_error& e) {
      std::fprintf(stderr, "featurerecon %s: error: %s\nTry 'featurerecon %s --help'.\n", c.name,
                   Outputs::name_targets(e.what()).c_str(), c.name);
      return 2;
    } catch (const std::bad_alloc&) {
      std::fprintf(
          stderr,
          "featurerecon %s: error: out of memory (the input or a parameter asks for more than this "
          "machine has: a smaller radius, k, count or size, or a larger spacing or interval, needs less)\n",
          c.name);
      return 1;
    } catch (const std::exception& e) {
      std::fprintf(stderr, "featurerecon %s: error: %s\n", c.name,
                   name_option_flags(Outputs::name_targets(e.what())).c_str());
      return 1;
    }
  }
  std::fprintf(stderr, "featurerecon: unknown command '%s'\nTry 'featurerecon --help'.\n", name.c_str());
  return 2;
}
