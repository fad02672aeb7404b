# SPDX-License-Identifier: GPL-3.0-or-later
# Runs the featurerecon program like a user: exit codes, error messages, written files.
# -DFEATURERECON=<program> -DDATA=<test/data> -DWORK=<scratch directory>
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
set(failures 0)

# expect(NAME EXIT_CODE REGEX_ON_OUTPUT args...)
function(expect name code regex)
  execute_process(COMMAND ${FEATURERECON} ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  set(all "${out}${err}")
  if(NOT rc EQUAL code)
    message(SEND_ERROR "${name}: exit ${rc}, expected ${code}\n${all}")
  elseif(NOT all MATCHES "${regex}")
    message(SEND_ERROR "${name}: output does not match '${regex}':\n${all}")
  else()
    message(STATUS "ok: ${name}")
  endif()
  set(last_output "${out}" PARENT_SCOPE)
endfunction()

# expect_count(FILE REGEX N): FILE contains REGEX exactly N times.
function(expect_count file regex n)
  file(READ ${file} text)
  string(REGEX MATCHALL "${regex}" found "${text}")
  list(LENGTH found count)
  if(NOT count EQUAL n)
    message(SEND_ERROR "${file}: ${count} matches of '${regex}', expected ${n}")
  endif()
endfunction()

expect(help 0 "rips.*reeb" --help)
expect(rips_help 0 "usage: featurerecon rips --points FILE" rips --help)
expect(reeb_help 0 "usage: featurerecon reeb --complex" reeb --help)
expect(unknown_command 2 "unknown command 'frobnicate'" frobnicate)
expect(missing_out 2 "missing required option --out.*featurerecon rips --help" rips --points ${DATA}/figure_eight.xyz --radius 1)
expect(both_scales 2 "exactly one of --radius R and --knn K" rips --points ${DATA}/figure_eight.xyz --radius 1 --knn 3 --out ${WORK}/x.txt)
expect(negative_radius 2 "--radius must be >= 0" rips --points ${DATA}/figure_eight.xyz --radius -1 --out ${WORK}/x.txt)
expect(bad_number 2 "--radius must be a finite number, got 'abc'" rips --points ${DATA}/figure_eight.xyz --radius abc --out ${WORK}/x.txt)
expect(unknown_option 2 "unknown option '--radus'" rips --points ${DATA}/figure_eight.xyz --radus 1 --out ${WORK}/x.txt)
expect(missing_file 1 "cannot open" rips --points ${WORK}/none.xyz --radius 1 --out ${WORK}/x.txt)

# A bad point file is reported with its line, and nothing is written.
file(WRITE ${WORK}/bad.xyz "0 0\n1 1\n2 nan\n")
expect(bad_points 1 "bad.xyz:3: coordinate is not finite" rips --points ${WORK}/bad.xyz --radius 1 --out ${WORK}/bad_out.txt)
if(EXISTS ${WORK}/bad_out.txt)
  message(SEND_ERROR "bad_points: an output file was written")
endif()
file(WRITE ${WORK}/bad_complex.txt "3 1\n0 0 0 0\n1 0 0 1\n2 0 0 2\n0 5\n")
expect(bad_complex 1 "bad_complex.txt:5: vertex index 5 out of range" reeb --complex ${WORK}/bad_complex.txt --json)

# The figure-eight sample: two loops, one component.
expect(rips 0 "wrote .*fig8.txt: 400 vertices" rips --points ${DATA}/figure_eight.xyz --radius 0.6 --out ${WORK}/fig8.txt --quiet)
expect(reeb_json 0 "\"loops\": 2,.*\"components\": 1,.*\"seconds\": " reeb --complex ${WORK}/fig8.txt --json)
foreach(key vertices edges triangles nodes arcs loops minima maxima up_forks down_forks components seconds)
  if(NOT last_output MATCHES "\"${key}\": ")
    message(SEND_ERROR "reeb --json: missing key ${key}: ${last_output}")
  endif()
endforeach()
expect(knn 0 "wrote .*fig8_knn.txt" rips --points ${DATA}/figure_eight.xyz --knn 12 --out ${WORK}/fig8_knn.txt --quiet)
expect(reeb_text 0 "Reeb graph: .* 2 loops" reeb --complex ${WORK}/fig8_knn.txt)
expect(brute_force 0 "wrote" rips --points ${DATA}/figure_eight.xyz --radius 0.6 --search brute-force --out ${WORK}/fig8_bf.txt --quiet)
file(READ ${WORK}/fig8.txt a)
file(READ ${WORK}/fig8_bf.txt b)
if(NOT a STREQUAL b)
  message(SEND_ERROR "kd-tree and brute-force searches wrote different complexes")
endif()

# Same input, same bytes.
expect(rips_again 0 "wrote" rips --points ${DATA}/figure_eight.xyz --radius 0.6 --out ${WORK}/fig8_again.txt --quiet)
file(READ ${WORK}/fig8_again.txt c)
if(NOT a STREQUAL c)
  message(SEND_ERROR "two runs on the same input wrote different complexes")
endif()

# Empty input is not an error.
file(WRITE ${WORK}/empty.xyz "# no points\n")
expect(rips_empty 0 "wrote .*empty.txt: 0 vertices" rips --points ${WORK}/empty.xyz --radius 1 --out ${WORK}/empty.txt --quiet)
expect(reeb_empty 0 "\"vertices\": 0,.*\"nodes\": 0,.*\"components\": 0" reeb --complex ${WORK}/empty.txt --json)
# One point in 5 dimensions, then duplicates.
file(WRITE ${WORK}/one.xyz "1 2 3 4 5\n")
expect(rips_one 0 "1 vertices, 0 edges.*dimension 5" rips --points ${WORK}/one.xyz --radius 1 --out ${WORK}/one.txt --quiet)
expect(reeb_one 0 "\"nodes\": 1,.*\"minima\": 1, \"maxima\": 1" reeb --complex ${WORK}/one.txt --json)
file(WRITE ${WORK}/dup.xyz "0 0\n0 0\n0 0\n3 0\n")
expect(rips_dup 0 "4 vertices, 3 edges, 1 triangles, 2 components" rips --points ${WORK}/dup.xyz --radius 0 --out ${WORK}/dup.txt --quiet)

# Persistence pairs: the figure-eight has two loops, each a [birth, death] pair with birth > death.
expect(reeb_persistence 0 "\"loops\": 2,.*\"branch_pairs\": \\[.*\"loop_pairs\": \\[\\[[-0-9.e]+, [-0-9.e]+\\], \\[[-0-9.e]+, [-0-9.e]+\\]\\]}" reeb --complex ${WORK}/fig8.txt --json --persistence)
expect(persistence_without_json 2 "--persistence goes with --json" reeb --complex ${WORK}/fig8.txt --persistence)

# evaluate-map on the shipped reference maps reproduces the published score (james vs crp, 15 m: F = .641).
set(M ${DATA}/chicago_maps/chicago)
expect(evaluate_map 0 "\"precision\": 0\\.93[0-9]*, \"recall\": 0\\.48[0-9]*, \"f_score\": 0\\.64[0-9]*" evaluate-map ${M}_gt_crp_vertices.txt ${M}_gt_crp_edges.txt ${M}_james_vertices.txt ${M}_james_edges.txt)
expect(evaluate_map_args 2 "expected four files" evaluate-map ${M}_gt_crp_vertices.txt)
expect(evaluate_map_crop_radius 2 "--crop-radius goes with --crop-to-tracks" evaluate-map ${M}_gt_crp_vertices.txt ${M}_gt_crp_edges.txt ${M}_james_vertices.txt ${M}_james_edges.txt --crop-radius 10)
file(WRITE ${WORK}/bad_edges.txt "1,1,99999\n")
expect(evaluate_map_bad 1 "bad_edges.txt:1: unknown vertex id 99999" evaluate-map ${M}_gt_crp_vertices.txt ${WORK}/bad_edges.txt ${M}_james_vertices.txt ${M}_james_edges.txt)
# Cropping to traces: a tracks file covering nothing removes every ground-truth edge.
file(WRITE ${WORK}/far_tracks.txt "0 0 0 0\n")
expect(evaluate_map_crop 0 "\"ground_truth_edges\": 0,.*\"ground_truth_edges_before_crop\": 1182" evaluate-map ${M}_gt_crp_vertices.txt ${M}_gt_crp_edges.txt ${M}_james_vertices.txt ${M}_james_edges.txt --crop-to-tracks ${WORK}/far_tracks.txt)

# Simplification: the figure-eight keeps its two loops at delta = 1 and loses them at delta = 20.
expect(reeb_simplify 0 "\"loops\": 2,.*\"removed_loops\": 0" reeb --complex ${WORK}/fig8.txt --json --simplify 1)
expect(reeb_simplify_all 0 "\"loops\": 0,.*\"removed_loops\": 2" reeb --complex ${WORK}/fig8.txt --json --simplify 20)
expect(reeb_simplify_negative 2 "--simplify must be >= 0" reeb --complex ${WORK}/fig8.txt --simplify -1)

# skeleton: the figure-eight sample gives a graph with two loops, written as a road map that evaluate-map reads.
expect(skeleton 0 "\"loops\": 2, \"components\": 1," skeleton --points ${DATA}/figure_eight.xyz --radius 0.6 --delta 1 --out-vertices ${WORK}/sk_v.txt --out-edges ${WORK}/sk_e.txt --quiet)
expect(skeleton_self_score 0 "\"precision\": 1, \"recall\": 1, \"f_score\": 1," evaluate-map ${WORK}/sk_v.txt ${WORK}/sk_e.txt ${WORK}/sk_v.txt ${WORK}/sk_e.txt --threshold 1)
expect(skeleton_source 2 "exactly one of --points FILE, --tracks FILE, --distance-matrix FILE and --graph FILE" skeleton --radius 1 --out-vertices ${WORK}/a --out-edges ${WORK}/b)
expect(skeleton_two_sources 2 "exactly one of" skeleton --points ${DATA}/figure_eight.xyz --graph ${DATA}/figure_eight_graph.txt --out-vertices ${WORK}/a --out-edges ${WORK}/b)
expect(skeleton_radius_required 2 "--radius R is required with --points" skeleton --points ${DATA}/figure_eight.xyz --out-vertices ${WORK}/a --out-edges ${WORK}/b)
expect(skeleton_graph_radius 2 "--radius does not apply to --graph" skeleton --graph ${DATA}/figure_eight_graph.txt --radius 1 --out-vertices ${WORK}/a --out-edges ${WORK}/b)
expect(skeleton_gps_option 2 "apply to --tracks only" skeleton --points ${DATA}/figure_eight.xyz --radius 0.6 --link-gap 3 --out-vertices ${WORK}/a --out-edges ${WORK}/b)

# The same figure-eight as a distance matrix (every 4th point) and as a graph: two loops, one component.
expect(skeleton_distance_matrix 0 "\"points\": 100, .*\"loops\": 2, \"components\": 1," skeleton --distance-matrix ${DATA}/figure_eight_distances.txt --radius 0.6 --delta 1 --out-vertices ${WORK}/dm_v.txt --out-edges ${WORK}/dm_e.txt --quiet)
expect(skeleton_graph 0 "\"rips_edges\": 232, .*\"loops\": 2, \"components\": 1," skeleton --graph ${DATA}/figure_eight_graph.txt --delta 1 --out-vertices ${WORK}/g_v.txt --out-edges ${WORK}/g_e.txt --quiet)
expect(skeleton_not_square 2 "a distance matrix needs n rows of n numbers; got 400 rows of 2" skeleton --distance-matrix ${DATA}/figure_eight.xyz --radius 1 --out-vertices ${WORK}/a --out-edges ${WORK}/b)
file(WRITE ${WORK}/asym.txt "0 1\n2 0\n")
expect(skeleton_asymmetric 1 "not symmetric at \\(0, 1\\)" skeleton --distance-matrix ${WORK}/asym.txt --radius 1 --out-vertices ${WORK}/a --out-edges ${WORK}/b)

# GPS tracks around one block with a dead-end street: defaults come from the median step (printed), the map has
# the block's loop and the spur, in one piece.
expect(skeleton_tracks 0 "\"radius\": 25\\.58[0-9]*, .*\"loops\": 1, \"components\": 1,.*\"trips\": 8, \"median_step\": 25\\.58" skeleton --tracks ${DATA}/block_tracks.txt --out-vertices ${WORK}/t_v.txt --out-edges ${WORK}/t_e.txt --quiet)
expect(skeleton_tracks_degree 0 "\"nodes\": 4, \"arcs\": 4" skeleton --tracks ${DATA}/block_tracks.txt --out-vertices ${WORK}/t_v.txt --out-edges ${WORK}/t_e.txt --quiet)
expect(skeleton_tracks_heading 2 "--heading-tolerance must be in \\[0, 180\\]" skeleton --tracks ${DATA}/block_tracks.txt --heading-tolerance 200 --out-vertices ${WORK}/a --out-edges ${WORK}/b)

# Chicago (the bundled 118k fixes) with the defaults: F-score at 15 m against the ground truth cropped to the
# traces (trk25) stays at 0.65 or more (0.659 when pinned; Kharita 0.671).
execute_process(COMMAND gzip -dc ${DATA}/../../data/gps/chicago/tracks.txt.gz OUTPUT_FILE ${WORK}/chicago_tracks.txt RESULT_VARIABLE gz)
if(NOT gz EQUAL 0)
  message(SEND_ERROR "cannot decompress the bundled Chicago tracks")
endif()
expect(skeleton_chicago 0 "\"points\": 118360, .*\"trips\": 889" skeleton --tracks ${WORK}/chicago_tracks.txt --out-vertices ${WORK}/c_v.txt --out-edges ${WORK}/c_e.txt --quiet)
expect(skeleton_chicago_score 0 "\"f_score\": 0\\.(6[5-9]|[7-9])[0-9]*," evaluate-map ${M}_gt_trk25_vertices.txt ${M}_gt_trk25_edges.txt ${WORK}/c_v.txt ${WORK}/c_e.txt)

# The skeleton's other formats: GraphML, GeoJSON, PLY, SVG, with the right counts (two loops that share a
# down-fork and an up-fork: 4 nodes, 5 arcs once the spurs at the base point and the farthest point are trimmed).
expect(skeleton_formats 0 "\"nodes\": 4, \"arcs\": 5" skeleton --points ${DATA}/figure_eight.xyz --radius 0.6 --delta 1 --out-vertices ${WORK}/f_v.txt --out-edges ${WORK}/f_e.txt --graphml ${WORK}/f.graphml --geojson ${WORK}/f.geojson --ply ${WORK}/f.ply --svg ${WORK}/f.svg --quiet)
expect_count(${WORK}/f.graphml "<node id=" 4)
expect_count(${WORK}/f.graphml "<edge id=" 5)
expect_count(${WORK}/f.geojson "\"LineString\"" 5)
expect_count(${WORK}/f.geojson "\"Point\"" 4)
expect_count(${WORK}/f.svg "<polyline" 5)
file(STRINGS ${WORK}/f.ply ply_header LIMIT_COUNT 6)
if(NOT ply_header MATCHES "element vertex [0-9]+")
  message(SEND_ERROR "PLY header: ${ply_header}")
endif()

# sample: a thin wall (two 20 x 20 sheets of unit spacing, 0.5 apart, opposite normals) as XYZ with normals.
set(wall "")
set(wall_plain "")
foreach(i RANGE 19)
  foreach(j RANGE 19)
    string(APPEND wall "${i} ${j} 0 0 0 -1\n${i}.25 ${j}.25 0.5 0 0 1\n")
    string(APPEND wall_plain "${i} ${j} 0\n${i}.25 ${j}.25 0.5\n")
  endforeach()
endforeach()
file(WRITE ${WORK}/wall.xyz "${wall}")
file(WRITE ${WORK}/wall_plain.xyz "${wall_plain}")
expect(sample_help 0 "usage: featurerecon sample --input FILE" sample --help)
expect(sample_no_size 2 "give --count M" sample --input ${WORK}/wall.xyz --out ${WORK}/s.xyz)
expect(sample_too_many 2 "--count 900 exceeds the 800 points" sample --input ${WORK}/wall.xyz --count 900 --out ${WORK}/s.xyz)
expect(sample_bad_method 2 "--method must be elimination or darts" sample --input ${WORK}/wall.xyz --count 9 --method x --out ${WORK}/s.xyz)
expect(sample_bad_format 1 "unknown point-cloud format '.txt'" sample --input ${WORK}/bad.xyz.txt --count 9 --out ${WORK}/s.xyz)
expect(sample_euclidean 0 "\"kept\": 200,.*\"normals\": \"file\"" sample --input ${WORK}/wall.xyz --count 200 --out ${WORK}/euclid.xyz --quiet)
expect_count(${WORK}/euclid.xyz "\n" 200)
expect(sample_bilateral 0 "\"kept\": 200,.*\"sigma_feature\": 0.5" sample --input ${WORK}/wall.xyz --count 200 --sigma-feature 0.5 --out ${WORK}/bilateral.xyz --quiet)
# Bilateral sampling splits the budget between the two sheets (normals -1 and +1): 100 each, give or take.
file(STRINGS ${WORK}/bilateral.xyz lines REGEX " -1$")
list(LENGTH lines bottom)
if(bottom LESS 80 OR bottom GREATER 120)
  message(SEND_ERROR "sample_bilateral: ${bottom} of 200 samples on the bottom sheet, expected about 100")
endif()
# Same seed, same bytes; PLY and OFF outputs; darts with a radius and with a target count.
expect(sample_again 0 "\"kept\": 200" sample --input ${WORK}/wall.xyz --count 200 --sigma-feature 0.5 --out ${WORK}/bilateral2.xyz --quiet)
file(READ ${WORK}/bilateral.xyz b1)
file(READ ${WORK}/bilateral2.xyz b2)
if(NOT b1 STREQUAL b2)
  message(SEND_ERROR "sample: the same seed gave different output")
endif()
expect(sample_ply 0 "\"kept\": 50" sample --input ${WORK}/wall.xyz --count 50 --out ${WORK}/s.ply --quiet)
expect_count(${WORK}/s.ply "property double nx" 1)
expect(sample_off 0 "\"kept\": 50" sample --input ${WORK}/wall.xyz --count 50 --out ${WORK}/s.off --quiet)
expect(sample_darts 0 "\"method\": \"darts\"" sample --input ${WORK}/wall.xyz --radius 2.5 --method darts --out ${WORK}/d.xyz --quiet)
expect(sample_darts_count 0 "\"kept\": 60,.*\"method\": \"darts\"" sample --input ${WORK}/wall.xyz --count 60 --method darts --out ${WORK}/d.xyz --quiet)
# No normals in the file: estimated when the bilateral distance needs them.
expect(sample_estimate 0 "\"normals\": \"estimated\"" sample --input ${WORK}/wall_plain.xyz --count 100 --sigma-feature 0.5 --unoriented --out ${WORK}/e.xyz --quiet)
expect(sample_stats 0 "\"samples\": 200,.*\"relative_radius\": " sample-stats --input ${WORK}/euclid.xyz)
expect(sample_stats_2d 0 "\"dimension\": 2,.*\"average_minimum_distance\": " sample-stats --input ${DATA}/figure_eight.xyz)
expect(sample_stats_bad 2 "--intrinsic-dimension must be 2 or 3" sample-stats --input ${DATA}/figure_eight.xyz --intrinsic-dimension 4)
# A 2D set on the unit torus: the spectrum statistics and the radial power file.
set(torus "")
foreach(i RANGE 15)
  foreach(j RANGE 15)
    string(APPEND torus "0.${i}${j}1 0.${j}${i}7\n")
  endforeach()
endforeach()
file(WRITE ${WORK}/torus.txt "${torus}")
expect(sample_stats_spectrum 0 "\"effective_nyquist\": .*\"oscillation\": .*\"oscillation_band\": \\[" sample-stats --input ${WORK}/torus.txt --periodic --spectrum ${WORK}/spectrum.csv --quiet)
expect_count(${WORK}/spectrum.csv "\n" 98)  # header and annuli 0..96 (F = 6 sqrt(256))
expect(sample_stats_spectrum_range 0 "\"effective_nyquist\": " sample-stats --input ${WORK}/torus.txt --periodic --max-frequency 32 --spectrum ${WORK}/spectrum32.csv)
expect_count(${WORK}/spectrum32.csv "\n" 34)
expect(sample_stats_bad_frequency 2 "--max-frequency must be >= 1" sample-stats --input ${WORK}/torus.txt --periodic --max-frequency 0)
expect(sample_stats_frequency_needs_torus 2 "--max-frequency needs --periodic" sample-stats --input ${WORK}/torus.txt --max-frequency 8)
expect(sample_stats_spectrum_needs_torus 2 "--spectrum needs --periodic" sample-stats --input ${WORK}/torus.txt --spectrum ${WORK}/x.csv)
