# SPDX-License-Identifier: GPL-3.0-or-later
# skeleton from points, pictures (--image), distance matrices, graphs and tracks: options and their ranges,
# the estimated radius, thinning, merging, formats, pictures, outputs that cannot be written.
# Run by ctest as cli_skeleton with the variables of cli_common.cmake.
include(${CMAKE_CURRENT_LIST_DIR}/cli_common.cmake)

# A radius below the points' spacing: the skeleton is mostly single points; the warning gives their median
# nearest-neighbour distance (brute force: 0.058117 for the 400 points, 0.2208 for the 100 rows of the matrix).
expect(skeleton_radius_below_spacing 0 "warning: at radius 0.01 the Rips graph has 1 edge for 400 points \\(fewer than one neighbour per point; 398 without any\\).* the median distance from a point to its nearest neighbour is 0.0581: give --radius above it" skeleton --points ${DATA}/figure_eight.xyz --radius 0.01 --out-vertices ${WORK}/rs_v.txt --out-edges ${WORK}/rs_e.txt --quiet)
expect(skeleton_radius_below_spacing_matrix 0 "at radius 0.05 the Rips graph has 0 edges for 100 points \\(fewer than one neighbour per point; 100 without any\\).* nearest neighbour is 0.221: " skeleton --distance-matrix ${DATA}/figure_eight_distances.txt --radius 0.05 --out-vertices ${WORK}/rs_v.txt --out-edges ${WORK}/rs_e.txt --quiet)
execute_process(COMMAND ${FEATURERECON} skeleton --points ${DATA}/figure_eight.xyz --radius 0.6 --out-vertices ${WORK}/rs_v.txt
                        --out-edges ${WORK}/rs_e.txt --quiet RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0 OR err MATCHES "warning")
  message(SEND_ERROR "skeleton_radius_above_spacing: exit ${rc}, a warning where the radius joins the points:\n${err}")
endif()

# skeleton: the figure-eight sample gives a graph with two loops, written as a road map that evaluate-map reads.
expect(skeleton 0 "\"loops\": 2, \"components\": 1," skeleton --points ${DATA}/figure_eight.xyz --radius 0.6 --delta 1 --out-vertices ${WORK}/sk_v.txt --out-edges ${WORK}/sk_e.txt --quiet)
# --max-gap: 0 draws every arc's gaps straight (parsed, same topology; "max_gap": null, nothing bridged); NaN and
# negative values (which turned it off before the library's FeatureRecon::automatic) are refused.
# Above 3-D the points are drawn in the skeleton's PCA frame: the figure-eight (8 tall, 4 wide) padded to 5-D
# lies along its first principal axis, which the picture draws horizontally, so the picture is about half as
# tall as wide. Drawn by their raw coordinates (as before), the points stood upright and filled the full height.
file(STRINGS ${DATA}/figure_eight.xyz eight_lines REGEX "^[^#]")
set(eight_5d "")
foreach(line IN LISTS eight_lines)
  string(APPEND eight_5d "${line} 0 0 0\n")
endforeach()
file(WRITE ${WORK}/eight_5d.xyz "${eight_5d}")
expect(skeleton_5d_picture 0 "\"loops\": 2," skeleton --points ${WORK}/eight_5d.xyz --radius 0.6 --delta 1
       --out-vertices ${WORK}/e5_v.txt --out-edges ${WORK}/e5_e.txt --svg ${WORK}/e5.svg --quiet)
expect_count(${WORK}/e5.svg "<circle cx=\"[0-9.]+\" cy=\"(7[0-9][0-9]|[89][0-9][0-9]|1[0-9][0-9][0-9])\\." 0)
expect(skeleton_max_gap_off 0 "\"loops\": 2, \"components\": 1," skeleton --points ${DATA}/figure_eight.xyz --radius 0.6 --delta 1 --max-gap 0 --out-vertices ${WORK}/a --out-edges ${WORK}/b --quiet)
expect(skeleton_max_gap_off_reported 0 "\"max_gap\": 0," skeleton --points ${DATA}/figure_eight.xyz --radius 0.6 --delta 1 --max-gap 0 --out-vertices ${WORK}/a --out-edges ${WORK}/b --quiet)
expect(skeleton_max_gap_negative 2 "--max-gap must be >= 0 \\(0: straight segments; unset: automatic\\), got '-1'" skeleton --points ${DATA}/figure_eight.xyz --radius 0.6 --max-gap -1 --out-vertices ${WORK}/a --out-edges ${WORK}/b)
# Branch nodes: the tangent circles of figure_eight.xyz share a stretch at radius 0.6, where the Reeb graph has
# an up-fork and a down-fork 1.25 apart; the default (twice the level width, 0.66) keeps both, 1.5 merges them.
expect(skeleton_branch_merge_default 0 "\"nodes\": 4, \"arcs\": 5, .*\"branch_merge\": 0\\.659[0-9]*, \"merged_branch_arcs\": 0, \"prune\": 0, \"level_width\": 0\\.329[0-9]*, \"max_gap\": 0\\.659" skeleton --points ${DATA}/figure_eight.xyz --radius 0.6 --delta 1 --out-vertices ${WORK}/a --out-edges ${WORK}/b --quiet)
expect(skeleton_branch_merge 0 "\"nodes\": 3, \"arcs\": 4, \"loops\": 2, .*\"branch_merge\": 1.5, \"merged_branch_arcs\": 1," skeleton --points ${DATA}/figure_eight.xyz --radius 0.6 --delta 1 --branch-merge 1.5 --out-vertices ${WORK}/a --out-edges ${WORK}/b --quiet)
expect(skeleton_branch_merge_bad 2 "--branch-merge must be finite and >= 0 \\(0: off\\), got '-1'" skeleton --points ${DATA}/figure_eight.xyz --radius 0.6 --branch-merge -1 --out-vertices ${WORK}/a --out-edges ${WORK}/b)
expect(skeleton_all_pruned 0 "\"nodes\": 0, .*warning: the skeleton is empty: pruning removed all 1 component\\(s\\), each of height at most 100 \\(--prune 0 keeps them\\)" skeleton --points ${DATA}/figure_eight.xyz --radius 0.6 --prune 100 --out-vertices ${WORK}/a --out-edges ${WORK}/b --quiet)
expect(skeleton_max_gap_nan 2 "--max-gap" skeleton --points ${DATA}/figure_eight.xyz --radius 0.6 --max-gap nan --out-vertices ${WORK}/a --out-edges ${WORK}/b)
# Edges 1e200 long: the automatic max_gap is twice the median edge (their squares overflowed: null, nothing bridged).
file(WRITE ${WORK}/huge_graph.txt "3 2\n0 0 0 0\n1e200 0 0 0\n2e200 0 0 0\n0 1\n1 2\n")
expect(skeleton_max_gap_huge 0 "\"level_width\": 1e\\+200, \"max_gap\": 2e\\+200," skeleton --graph ${WORK}/huge_graph.txt --out-vertices ${WORK}/a --out-edges ${WORK}/b --quiet)
expect(skeleton_self_score 0 "\"precision\": 1, \"recall\": 1, \"f_score\": 1," evaluate-map ${WORK}/sk_v.txt ${WORK}/sk_e.txt ${WORK}/sk_v.txt ${WORK}/sk_e.txt --threshold 1)
expect(skeleton_source 2 "exactly one of --points FILE, --image FILE, --tracks FILE, --distance-matrix FILE and --graph FILE" skeleton --radius 1 --out-vertices ${WORK}/a --out-edges ${WORK}/b)
# --image: the ink of a picture. A dark ring on white (ASCII PGM, 9 x 9) is one loop; its pixel centres are y up.
file(WRITE ${WORK}/ring.pgm "P2\n9 9\n255\n")
foreach(row 0 1 2 3 4 5 6 7 8)
  set(line "")
  foreach(column 0 1 2 3 4 5 6 7 8)
    math(EXPR dx "${column} - 4")
    math(EXPR dy "${row} - 4")
    math(EXPR r2 "${dx} * ${dx} + ${dy} * ${dy}")
    if(r2 GREATER_EQUAL 5 AND r2 LESS_EQUAL 13)
      string(APPEND line " 20")
    else()
      string(APPEND line " 250")
    endif()
  endforeach()
  file(APPEND ${WORK}/ring.pgm "${line}\n")
endforeach()
expect(skeleton_image_ring 0 "\"radius\": 1.5, \"delta\": 3, .*\"loops\": 1, \"components\": 1, .*\"image_width\": 9, \"image_height\": 9, \"ink\": \"dark\", \"ink_threshold\": 128" skeleton --image ${WORK}/ring.pgm --out-vertices ${WORK}/ring_v.txt --out-edges ${WORK}/ring_e.txt --quiet)
expect_count(${WORK}/ring_v.txt "^0,[0-9.]+,[0-9.]+\n" 1)
expect(skeleton_image_bright 0 "\"points\": 0,.*warning: the input holds no ink pixels \\(--ink, --ink-threshold\\)" skeleton --image ${WORK}/ring.pgm --ink bright --ink-threshold 251 --out-vertices ${WORK}/a --out-edges ${WORK}/b --quiet)
# The white: the disc inside the ring and the frame around it (a loop).
expect(skeleton_image_background 0 "\"points\": 49,.*\"loops\": 1, \"components\": 2," skeleton --image ${WORK}/ring.pgm --ink bright --out-vertices ${WORK}/a --out-edges ${WORK}/b --quiet)
# One dark pixel in the top row, third column of a 4 x 3 picture: a point at (2.5, 3 - 0.5).
file(WRITE ${WORK}/dot.pgm "P2\n4 3\n255\n255 255 0 255\n255 255 255 255\n255 255 255 255\n")
expect(skeleton_image_dot 0 "\"points\": 1,.*\"nodes\": 1, \"arcs\": 0," skeleton --image ${WORK}/dot.pgm --out-vertices ${WORK}/dot_v.txt --out-edges ${WORK}/dot_e.txt --quiet)
expect_count(${WORK}/dot_v.txt "^0,2\\.5,2\\.5\n$" 1)
# The 1,000 digits of the handwriting example: as many loops as the example's skeletons, one component per piece of ink.
# Their picture resolves the radius: the 1994 pixels of ink across at radius 1.5 get 3988 pixels (3 per radius) plus
# the margins, so ink pixels 2 apart are dots of radius 0.6 (a fifth of the radius) rather than the full 1, which
# filled every stroke at the 1000 pixels used before. --picture-size sets the page, the marks follow (0.3, the least).
expect(skeleton_image_digits 0 "\"loops\": 399, \"components\": 1032," skeleton --image ${PROJECT_DATA}/images/digits_1000.pgm --ink bright --out-vertices ${WORK}/a --out-edges ${WORK}/b --svg ${WORK}/digits.svg --quiet)
expect_count(${WORK}/digits.svg "viewBox=\"0 0 4008\\.00 414\\.00\"" 1)
expect_count(${WORK}/digits.svg "r=\"0\\.6[0-9]*\" fill=\"#c0c0c0\"" 51788)
expect_count(${WORK}/digits.svg "<polyline fill=\"none\" stroke-width=\"1\\.5[0-9]*\"" 2070)
expect(skeleton_picture_size 0 "\"loops\": 399," skeleton --image ${PROJECT_DATA}/images/digits_1000.pgm --ink bright --out-vertices ${WORK}/a --out-edges ${WORK}/b --svg ${WORK}/digits_small.svg --picture-size 1000 --quiet)
expect_count(${WORK}/digits_small.svg "viewBox=\"0 0 1020\\.00 " 1)
expect_count(${WORK}/digits_small.svg "r=\"0\\.3\" fill=\"#c0c0c0\"" 51788)
expect(skeleton_picture_size_range 2 "--picture-size must be an integer number of pixels in \\[100, 8192\\], got '99'" skeleton --points ${DATA}/figure_eight.xyz --radius 0.6 --out-vertices ${WORK}/a --out-edges ${WORK}/b --svg ${WORK}/x.svg --picture-size 99)
expect(skeleton_picture_size_alone 2 "--picture-size applies to the picture of --svg F" skeleton --points ${DATA}/figure_eight.xyz --radius 0.6 --out-vertices ${WORK}/a --out-edges ${WORK}/b --picture-size 500)
# Lengths derived from the radius (up to 5R) and the level width (2W) must stay finite: 1e308 made delta, repair and
# prune infinite (a library error naming internal fields, exit 1; with tracks at 5e307 an empty map and "prune": null).
expect(skeleton_radius_huge 2 "--radius must be at most 1e300 \\(lengths derived from it, up to 5R, must stay finite\\), got '5e307'" skeleton --tracks ${DATA}/block_tracks.txt --radius 5e307 --out-vertices ${WORK}/a --out-edges ${WORK}/b)
expect(skeleton_level_width_huge 2 "--level-width must be > 0 and at most 1e300 \\(2W must stay finite; unset: automatic\\), got '1e308'" skeleton --points ${DATA}/figure_eight.xyz --radius 0.3 --level-width 1e308 --out-vertices ${WORK}/a --out-edges ${WORK}/b)
expect(skeleton_level_width_negative 2 "--level-width must be > 0" skeleton --points ${DATA}/figure_eight.xyz --radius 0.3 --level-width -1 --out-vertices ${WORK}/a --out-edges ${WORK}/b)
expect(skeleton_level_width_zero 2 "--level-width must be > 0" skeleton --points ${DATA}/figure_eight.xyz --radius 0.3 --level-width 0 --out-vertices ${WORK}/a --out-edges ${WORK}/b)
# Tracks: as in the library, unset is automatic and 0 turns linking off; a negative link gap (no linking before)
# and a sample spacing of 0 (automatic before) are refused.
expect(skeleton_link_gap_off 0 "\"link_gap\": 0, .*\"trip_links\": 0," skeleton --tracks ${DATA}/block_tracks.txt --link-gap 0 --out-vertices ${WORK}/a --out-edges ${WORK}/b --quiet)
# Unlinked, the block's samples are pruned away: the merge does not run, and the JSON has no merge_ fields.
if(last_output MATCHES "merge_level_width|merge_samples")
  message(SEND_ERROR "skeleton_link_gap_off: the JSON reports a merge that did not run:\n${last_output}")
endif()
expect(skeleton_link_gap_negative 2 "--link-gap must be >= 0 metres and finite \\(0: no linking; unset: automatic\\), got '-1'" skeleton --tracks ${DATA}/block_tracks.txt --link-gap -1 --out-vertices ${WORK}/a --out-edges ${WORK}/b)
expect(skeleton_tracks_spacing_zero 2 "--sample-spacing must be > 0 with --tracks \\(unset: R/2\\), got '0'" skeleton --tracks ${DATA}/block_tracks.txt --sample-spacing 0 --out-vertices ${WORK}/a --out-edges ${WORK}/b)
expect(skeleton_image_ink 2 "--ink must be dark or bright, got 'grey'" skeleton --image ${WORK}/ring.pgm --ink grey --out-vertices ${WORK}/a --out-edges ${WORK}/b)
expect(skeleton_image_threshold 2 "--ink-threshold must be an integer grey level in \\[1, 255\\], got '0'" skeleton --image ${WORK}/ring.pgm --ink-threshold 0 --out-vertices ${WORK}/a --out-edges ${WORK}/b)
expect(skeleton_image_only 2 "--ink and --ink-threshold apply to --image only" skeleton --points ${DATA}/figure_eight.xyz --radius 0.6 --ink bright --out-vertices ${WORK}/a --out-edges ${WORK}/b)
expect(skeleton_image_missing 1 "no_such.png" skeleton --image ${WORK}/no_such.png --out-vertices ${WORK}/a --out-edges ${WORK}/b)
expect(skeleton_two_sources 2 "exactly one of" skeleton --points ${DATA}/figure_eight.xyz --graph ${DATA}/figure_eight_graph.txt --out-vertices ${WORK}/a --out-edges ${WORK}/b)
# Without --radius the radius, delta and thinning come from the data (estimate_rips_radius()); the JSON says so.
expect(skeleton_radius_estimated 0 "\"radius\": 0\\.594[0-9]*, \"delta\": 0\\.668[0-9]*, .*\"loops\": 2, \"components\": 1, .*\"radius_estimate\": {\"scale\": 0\\.297[0-9]*, \"intrinsic_dimension\": 1\\.1[0-9]*, \"mean_neighbours\": 9\\.21, \"gap_radius\": 0\\.594[0-9]*, \"distinct_points\": 400, \"reference_points\": 400}" skeleton --points ${DATA}/figure_eight.xyz --out-vertices ${WORK}/a --out-edges ${WORK}/b --quiet)
# Copies of every point are one point to the estimate (the Rips stage joins them): the same radius and skeleton.
file(READ ${DATA}/figure_eight.xyz figure_eight_points)
file(WRITE ${WORK}/figure_eight_thrice.xyz "${figure_eight_points}${figure_eight_points}${figure_eight_points}")
expect(skeleton_radius_estimated_copies 0 "\"points\": 1200, \"sampled\": 1200, \"radius\": 0\\.594[0-9]*, \"delta\": 0\\.668[0-9]*, .*\"loops\": 2, \"components\": 1, .*\"distinct_points\": 400," skeleton --points ${WORK}/figure_eight_thrice.xyz --out-vertices ${WORK}/a --out-edges ${WORK}/b --quiet)
expect(skeleton_matrix_radius_estimated 0 "\"points\": 100, .*\"loops\": 2, \"components\": 1, .*\"radius_estimate\": {\"scale\": 1," skeleton --distance-matrix ${DATA}/figure_eight_distances.txt --out-vertices ${WORK}/a --out-edges ${WORK}/b --quiet)
# Noise in many dimensions keeps every point far from all others: 1,500 points around a square loop (side 60) in
# the first two axes, integer noise (a sum of four draws from -1, 0, 1 of a linear congruential sequence) on all 24
# axes. Thinning within (R - gap radius) / 2 = 8.6 keeps 945 points and 6.3 million triangles, which a limit of
# 2 million refused; the command then thins farther (11.3: 202 points), says so, and still draws the loop.
set(state 12345)
set(noisy_square "")
foreach(i RANGE 1499)
  math(EXPR p "${i} * 240 / 1500")
  if(p LESS 60)
    set(x ${p})
    set(y 0)
  elseif(p LESS 120)
    set(x 60)
    math(EXPR y "${p} - 60")
  elseif(p LESS 180)
    math(EXPR x "180 - ${p}")
    set(y 60)
  else()
    set(x 0)
    math(EXPR y "240 - ${p}")
  endif()
  foreach(axis RANGE 23)
    set(noise 0)
    foreach(draw RANGE 3)
      math(EXPR state "(${state} * 1103515245 + 12345) % 2147483648")
      math(EXPR noise "${noise} + (${state} / 65536) % 3 - 1")
    endforeach()
    if(axis EQUAL 0)
      math(EXPR noise "${x} + ${noise}")
    elseif(axis EQUAL 1)
      math(EXPR noise "${y} + ${noise}")
    endif()
    string(APPEND noisy_square "${noise} ")
  endforeach()
  string(APPEND noisy_square "\n")
endforeach()
file(WRITE ${WORK}/noisy_square_24.xyz "${noisy_square}")
expect(skeleton_radius_estimated_thinning 0 "\"points\": 1500, \"sampled\": 202,.*\"loops\": 1, \"components\": 1,.*thinned at 11\\.31, beyond \\(R - gap radius\\) / 2 = 8\\.614" skeleton --points ${WORK}/noisy_square_24.xyz --max-triangles 2000000 --out-vertices ${WORK}/a --out-edges ${WORK}/b --quiet)
expect(skeleton_radius_estimated_thinning_within 0 "\"points\": 1500, \"sampled\": 945,.*\"loops\": 1, \"components\": 1," skeleton --points ${WORK}/noisy_square_24.xyz --out-vertices ${WORK}/a --out-edges ${WORK}/b --quiet)
# --sample-spacing 0 keeps every point (no thinning although the radius was estimated).
expect(skeleton_radius_estimated_no_thinning 0 "\"points\": 1500, \"sampled\": 1500," skeleton --points ${WORK}/noisy_square_24.xyz --sample-spacing 0 --out-vertices ${WORK}/a --out-edges ${WORK}/b --quiet)
if(last_error MATCHES "warning")
  message(SEND_ERROR "skeleton_radius_estimated_thinning_within: a warning without a limit to keep:\n${last_error}")
endif()
file(WRITE ${WORK}/one_point.xyz "1 2\n")
expect(skeleton_radius_one_point 0 "\"radius\": 0, .*\"nodes\": 1, .*\"intrinsic_dimension\": null" skeleton --points ${WORK}/one_point.xyz --out-vertices ${WORK}/a --out-edges ${WORK}/b --quiet)
expect(skeleton_graph_radius 2 "--radius does not apply to --graph" skeleton --graph ${DATA}/figure_eight_graph.txt --radius 1 --out-vertices ${WORK}/a --out-edges ${WORK}/b)
expect(skeleton_gps_option 2 "apply to --tracks only" skeleton --points ${DATA}/figure_eight.xyz --radius 0.6 --link-gap 3 --out-vertices ${WORK}/a --out-edges ${WORK}/b)

# The same figure-eight as a distance matrix (every 4th point) and as a graph: two loops, one component.
expect(skeleton_distance_matrix 0 "\"points\": 100, .*\"loops\": 2, \"components\": 1," skeleton --distance-matrix ${DATA}/figure_eight_distances.txt --radius 0.6 --delta 1 --out-vertices ${WORK}/dm_v.txt --out-edges ${WORK}/dm_e.txt --quiet)
expect(skeleton_graph 0 "\"rips_edges\": 232, .*\"loops\": 2, \"components\": 1," skeleton --graph ${DATA}/figure_eight_graph.txt --delta 1 --out-vertices ${WORK}/g_v.txt --out-edges ${WORK}/g_e.txt --quiet)
expect(skeleton_not_square 1 "figure_eight.xyz: a distance matrix needs n rows of n numbers; got 400 rows of 2" skeleton --distance-matrix ${DATA}/figure_eight.xyz --radius 1 --out-vertices ${WORK}/a --out-edges ${WORK}/b)
file(WRITE ${WORK}/asym.txt "0 1\n2 0\n")
expect(skeleton_asymmetric 1 "asym.txt:2: not symmetric: entry \\(1, 0\\) is " skeleton --distance-matrix ${WORK}/asym.txt --radius 1 --out-vertices ${WORK}/a --out-edges ${WORK}/b)
# A distance matrix's messages speak of rows and distances (they spoke of points and coordinates).
file(WRITE ${WORK}/ragged_dm.txt "0 1 2\n1 0\n2 1 0\n")
expect(skeleton_ragged_matrix 1 "ragged_dm.txt:2: row has 2 distances, the first row has 3" skeleton --distance-matrix ${WORK}/ragged_dm.txt --radius 1 --out-vertices ${WORK}/a --out-edges ${WORK}/b)
file(WRITE ${WORK}/nan_dm.txt "0 nan\nnan 0\n")
expect(skeleton_nan_matrix 1 "nan_dm.txt:1: distance is not finite \\('nan'\\)" skeleton --distance-matrix ${WORK}/nan_dm.txt --radius 1 --out-vertices ${WORK}/a --out-edges ${WORK}/b)

# GPS tracks around one block (200 x 100 m) with a 150 m dead-end street: defaults come from the median step
# (printed); before merging (--merge 0) the skeleton has the block's loop and the spur, in one piece.
expect(skeleton_tracks 0 "\"radius\": 25\\.58[0-9]*, .*\"loops\": 1, \"components\": 1,.*\"trips\": 8, \"median_step\": 25\\.58" skeleton --tracks ${DATA}/block_tracks.txt --merge 0 --out-vertices ${WORK}/t_v.txt --out-edges ${WORK}/t_e.txt --quiet)
expect(skeleton_tracks_degree 0 "\"nodes\": 4, \"arcs\": 4" skeleton --tracks ${DATA}/block_tracks.txt --merge 0 --out-vertices ${WORK}/t_v.txt --out-edges ${WORK}/t_e.txt --quiet)
# Without merging the map is the skeleton: its length, before and after (both were printed as 0).
expect(skeleton_tracks_unmerged_length 0 "\"merge_distance\": 0, \"length_before_merge\": 1323\\.09[0-9]*, \"length\": 1323\\.09" skeleton --tracks ${DATA}/block_tracks.txt --merge 0 --out-vertices ${WORK}/t_v.txt --out-edges ${WORK}/t_e.txt --quiet)
# Merging (default 8 m) draws the streets, driven both ways, once: about 720 m of lines (the block and the spur
# are 750 m) instead of about 1310, and the merged map (which the JSON describes) has the block's one loop (two
# in session 11, when a corner where the two directions cut differently stayed a thin loop).
expect(skeleton_tracks_merged 0 "\"loops\": 1, \"components\": 1,.*\"merge_distance\": 8, \"length_before_merge\": 1[23][0-9][0-9]\\.[0-9]*, \"length\": 7[0-9][0-9]\\.[0-9]*, \"merge_smoothing\": \"laplacian\", \"merge_smoothing_rounds\": 20, \"merge_level_width\": [0-9.]+, \"merge_max_gap\": [0-9.]+" skeleton --tracks ${DATA}/block_tracks.txt --out-vertices ${WORK}/t_v.txt --out-edges ${WORK}/t_e.txt --quiet)
# The written lines are drawn by the merge: --smoothing draws the skeleton before it, and the JSON says so.
# The merging stage's size: its spacing (a third of the 8 m), samples and complex.
expect(skeleton_tracks_merge_size 0 "\"merge_spacing\": 2\\.666[0-9]*, \"merge_samples\": [1-9][0-9]*, \"merge_rips_edges\": [1-9][0-9]*, \"merge_rips_triangles\": [1-9][0-9]*[,}]" skeleton --tracks ${DATA}/block_tracks.txt --out-vertices ${WORK}/t_v.txt --out-edges ${WORK}/t_e.txt --quiet)
expect(skeleton_tracks_merge_drawing 0 "\"smoothing\": \"taubin\", \"smoothing_rounds\": 0,.*\"merge_smoothing\": \"laplacian\", \"merge_smoothing_rounds\": 20," skeleton --tracks ${DATA}/block_tracks.txt --smoothing 0 --smoothing-method taubin --out-vertices ${WORK}/t_v.txt --out-edges ${WORK}/t_e.txt --quiet)
# Samples at the mean of their fixes by default; --first-point-positions keeps them where they were created.
expect(skeleton_tracks_mean_positions 0 "\"directed\": true, \"mean_positions\": true," skeleton --tracks ${DATA}/block_tracks.txt --out-vertices ${WORK}/t_v.txt --out-edges ${WORK}/t_e.txt --quiet)
# A directory with one trip per *.txt file (lines 'x y t', the map-construction benchmark's trips/trip_N.txt)
# gives the same map as the same trips in one file; other files in it are not read.
file(REMOVE_RECURSE ${WORK}/block_trips)
file(MAKE_DIRECTORY ${WORK}/block_trips)
file(STRINGS ${DATA}/block_tracks.txt block_lines REGEX "^[0-9]")
foreach(line IN LISTS block_lines)
  string(REGEX MATCH "^([0-9]+) (.*)$" _ "${line}")
  file(APPEND ${WORK}/block_trips/trip_${CMAKE_MATCH_1}.txt "${CMAKE_MATCH_2}\n")
endforeach()
file(WRITE ${WORK}/block_trips/README.md "not a trip\n")
expect(skeleton_tracks_directory 0 "\"trips\": 8," skeleton --tracks ${WORK}/block_trips --out-vertices ${WORK}/td_v.txt --out-edges ${WORK}/td_e.txt --quiet)
expect_same_file(${WORK}/t_v.txt ${WORK}/td_v.txt "skeleton_tracks_directory: vertices")
expect_same_file(${WORK}/t_e.txt ${WORK}/td_e.txt "skeleton_tracks_directory: edges")
# Natural order of the names (trip_2 is trip 0, trip_10 trip 1), and errors name the trip's file and line.
file(REMOVE_RECURSE ${WORK}/far_trips)
file(MAKE_DIRECTORY ${WORK}/far_trips)
file(WRITE ${WORK}/far_trips/trip_2.txt "0 0 0\n10 0 1\n20 0 2\n")
file(WRITE ${WORK}/far_trips/trip_10.txt "# x y t\n0 0 0\n10 0 1\n1e17 0 2\n")
expect(skeleton_tracks_directory_located 1 "sample_gps_traces: trip 1, fix 2 at \\(1e\\+17, 0\\) .* \\[[^]]*far_trips/trip_10.txt:4, trip id 'trip_10'\\]" skeleton --tracks ${WORK}/far_trips --out-vertices ${WORK}/a --out-edges ${WORK}/b --quiet)
file(WRITE ${WORK}/far_trips/trip_10.txt "0 0 0\n10 95 1\n")
expect(skeleton_tracks_directory_lonlat 1 "far_trips/trip_10.txt:2: --lonlat: \\(10, 95\\) is not a longitude" skeleton --tracks ${WORK}/far_trips --lonlat --out-vertices ${WORK}/a --out-edges ${WORK}/b --quiet)
file(WRITE ${WORK}/deg_v.txt "0,10,50\n1,10.001,50\n")
file(WRITE ${WORK}/deg_e.txt "0,0,1\n")
expect(evaluate_map_crop_directory_lonlat 1 "far_trips/trip_10.txt:2: --lonlat: \\(10, 95\\) is not a longitude" evaluate-map ${WORK}/deg_v.txt ${WORK}/deg_e.txt ${WORK}/deg_v.txt ${WORK}/deg_e.txt --lonlat --crop-to-tracks ${WORK}/far_trips)
file(WRITE ${WORK}/far_trips/trip_10.txt "0 0 0 4\n")
expect(skeleton_tracks_directory_columns 1 "far_trips/trip_10.txt:1: expected 'x y \\[t\\]' \\(a directory of tracks holds one trip per file\\), got 4 values" skeleton --tracks ${WORK}/far_trips --out-vertices ${WORK}/a --out-edges ${WORK}/b --quiet)
# One trip file of lines 'x y t' given instead of its directory: every line a trip of one fix; said (also when
# an x repeats, a stationary vehicle, and two lines make one trip), not for the directory itself.
expect(skeleton_tracks_one_trip_file 0 "warning: .*block_trips/trip_0.txt: its 25 fixes make 25 trips, fewer than two a trip .*give its directory" skeleton --tracks ${WORK}/block_trips/trip_0.txt --out-vertices ${WORK}/a --out-edges ${WORK}/b --quiet)
expect(evaluate_map_one_trip_file 0 "warning: .*block_trips/trip_0.txt: its 25 fixes make 25 trips" evaluate-map ${M}_gt_crp_vertices.txt ${M}_gt_crp_edges.txt ${M}_james_vertices.txt ${M}_james_edges.txt --tracks ${WORK}/block_trips/trip_0.txt --quiet)
file(READ ${WORK}/block_trips/trip_0.txt trip_0_text)
string(REGEX MATCH "^[^\n]*\n" trip_0_first "${trip_0_text}")
file(WRITE ${WORK}/trip_0_stop.txt "${trip_0_text}${trip_0_first}")
expect(skeleton_tracks_one_trip_file_stop 0 "warning: .*trip_0_stop.txt: its 26 fixes make 25 trips" skeleton --tracks ${WORK}/trip_0_stop.txt --out-vertices ${WORK}/a --out-edges ${WORK}/b --quiet)
expect(skeleton_tracks_directory_no_warning 0 "\"trips\": 8," skeleton --tracks ${WORK}/block_trips --out-vertices ${WORK}/a --out-edges ${WORK}/b --quiet)
if(last_error MATCHES "warning")
  message(SEND_ERROR "skeleton_tracks_directory_no_warning: a warning for a directory of trips:\n${last_error}")
endif()
# A *.txt entry that cannot be read (a broken link) is named, not left out.
file(CREATE_LINK ${WORK}/nowhere.txt ${WORK}/far_trips/trip_5.txt SYMBOLIC)
expect(skeleton_tracks_directory_broken_link 1 "far_trips/trip_5.txt: cannot read this trip file" skeleton --tracks ${WORK}/far_trips --out-vertices ${WORK}/a --out-edges ${WORK}/b --quiet)
file(REMOVE_RECURSE ${WORK}/no_trips)
file(MAKE_DIRECTORY ${WORK}/no_trips)
file(WRITE ${WORK}/no_trips/trips.csv "0 0 0\n")
expect(skeleton_tracks_directory_empty 1 "no_trips: a directory of tracks holds one trip per '\\*.txt' file \\(lines 'x y \\[t\\]'\\), but it has none" skeleton --tracks ${WORK}/no_trips --out-vertices ${WORK}/a --out-edges ${WORK}/b --quiet)
expect(skeleton_tracks_first_point 0 "\"components\": 1,.*\"mean_positions\": false," skeleton --tracks ${DATA}/block_tracks.txt --first-point-positions --out-vertices ${WORK}/t_v.txt --out-edges ${WORK}/t_e.txt --quiet)
expect(skeleton_first_point_points 2 "apply to --tracks only" skeleton --points ${DATA}/figure_eight.xyz --radius 0.6 --first-point-positions --out-vertices ${WORK}/a --out-edges ${WORK}/b)
expect(skeleton_segment_support_points 2 "apply to --tracks only" skeleton --points ${DATA}/figure_eight.xyz --radius 0.6 --segment-support 20 --out-vertices ${WORK}/a --out-edges ${WORK}/b)
expect(skeleton_segment_support_negative 2 "--segment-support must be >= 0 metres" skeleton --tracks ${DATA}/block_tracks.txt --segment-support -1 --out-vertices ${WORK}/t_v.txt --out-edges ${WORK}/t_e.txt --quiet)
expect(skeleton_segment_support_off 0 "\"segment_support\": 0, \"segment_turn_tolerance\": 30, \"checked_segments\": 0, \"confirmed_segments\": 0, \"straight_checked\": 0, \"straight_confirmed\": 0, \"min_straight_confirmed_fraction\": 0.75, \"turn_rule_used\": false, \"straight_segments\": 0, \"linked_segments\": 0, \"all_segments_used\": true" skeleton --tracks ${DATA}/block_tracks.txt --segment-support 0 --out-vertices ${WORK}/t_v.txt --out-edges ${WORK}/t_e.txt --quiet)
expect(skeleton_segment_support_default 0 "\"components\": 1,.*\"segment_support\": 20, \"segment_turn_tolerance\": 30, \"checked_segments\": [0-9]+, \"confirmed_segments\": [0-9]+, \"straight_checked\": [0-9]+, \"straight_confirmed\": [0-9]+, \"min_straight_confirmed_fraction\": 0.75, \"turn_rule_used\": (true|false), \"straight_segments\": [0-9]+, \"linked_segments\": [0-9]+, \"all_segments_used\": (true|false)" skeleton --tracks ${DATA}/block_tracks.txt --out-vertices ${WORK}/t_v.txt --out-edges ${WORK}/t_e.txt --quiet)
expect(skeleton_segment_support 0 "\"segment_support\": 35, \"segment_turn_tolerance\": 10," skeleton --tracks ${DATA}/block_tracks.txt --segment-support 35 --segment-turn-tolerance 10 --out-vertices ${WORK}/t_v.txt --out-edges ${WORK}/t_e.txt --quiet)
expect(skeleton_straight_confirmed_bad 2 "--straight-confirmed must be in \\[0, 1\\]" skeleton --tracks ${DATA}/block_tracks.txt --straight-confirmed 1.5 --out-vertices ${WORK}/t_v.txt --out-edges ${WORK}/t_e.txt --quiet)
expect(skeleton_straight_confirmed_points 2 "--straight-confirmed, --quiet-ends, --local-support, --min-local-support and --merge apply to --tracks only" skeleton --points ${DATA}/figure_eight.xyz --radius 0.6 --straight-confirmed 0.5 --out-vertices ${WORK}/a --out-edges ${WORK}/b)
expect(skeleton_min_confirmed_bad 2 "--min-confirmed must be in \\[0, 1\\]" skeleton --tracks ${DATA}/block_tracks.txt --min-confirmed 1.5 --out-vertices ${WORK}/t_v.txt --out-edges ${WORK}/t_e.txt --quiet)
expect(skeleton_min_confirmed_points 2 "--min-confirmed, --segment-support, .* apply to --tracks only" skeleton --points ${DATA}/figure_eight.xyz --radius 0.6 --min-confirmed 0.5 --out-vertices ${WORK}/a --out-edges ${WORK}/b)
# 150 trips every 45 s (166 fixes): no checked segment is confirmed, the check stands down and says so;
# --min-confirmed 0 keeps it (and the warning is not given).
expect(synthetic_city_too_sparse 0 "\"seed\": 5}" synthetic-city --trips 150 --interval 45 --seed 5 --out-tracks ${WORK}/vs_t.txt --out-vertices ${WORK}/vs_gv.txt --out-edges ${WORK}/vs_ge.txt)
expect(skeleton_check_stands_down 0 "\"checked_segments\": 40, \"confirmed_segments\": 0,.*\"all_segments_used\": true, \"min_confirmed_fraction\": 0.2,.*\"stand_down_path\": 2.5, \"joined_segments\": 0,.*warning: 0 of 40 checked segments between fixes are confirmed by other fixes at the segment support, below --min-confirmed 0.2: the check stands down, taking the traces as too sparse to judge one another, and every segment up to the link gap \\([0-9.]+ m\\) is densified but the 0 whose ends" skeleton --tracks ${WORK}/vs_t.txt --out-vertices ${WORK}/vs_v.txt --out-edges ${WORK}/vs_e.txt --quiet)
expect(skeleton_check_kept 0 "\"all_segments_used\": false, \"min_confirmed_fraction\": 0," skeleton --tracks ${WORK}/vs_t.txt --min-confirmed 0 --out-vertices ${WORK}/vs_v.txt --out-edges ${WORK}/vs_e.txt --quiet)
if(last_error MATCHES "too sparse to judge")
  message(SEND_ERROR "skeleton_check_kept: the stand-down warning was given with --min-confirmed 0")
endif()
# The stand-down leaves the segments whose ends the fixes alone join (--stand-down-path): 2,000 trips every
# 60 s confirm 34 of 243 checked segments at the segment support (30 at the local distance), 172 of the others
# are chords whose ends the fixes join (F 0.612; 0.493 when the stand-down densified every segment, as
# --stand-down-path 0 still does; -0 prints as 0).
expect(synthetic_city_fleet 0 "\"seed\": 3}" synthetic-city --trips 2000 --interval 60 --seed 3 --out-tracks ${WORK}/fl_t.txt --out-vertices ${WORK}/fl_gv.txt --out-edges ${WORK}/fl_ge.txt)
expect(skeleton_stand_down_joins 0 "\"all_segments_used\": true, .*\"quiet_segments\": [0-9]+, \"stand_down_path\": 2.5, \"joined_segments\": 172,.*warning: 34 of 243 checked segments .* every segment up to the link gap \\([0-9.]+ m\\) is densified but the 172 whose ends the fixes alone join \\(--stand-down-path 2.5\\)" skeleton --tracks ${WORK}/fl_t.txt --out-vertices ${WORK}/fl_v.txt --out-edges ${WORK}/fl_e.txt --quiet)
expect(evaluate_stand_down_joins 0 "\"f_score\": 0\\.61" evaluate-map ${WORK}/fl_gv.txt ${WORK}/fl_ge.txt ${WORK}/fl_v.txt ${WORK}/fl_e.txt --quiet)
expect(skeleton_stand_down_every_segment 0 "\"stand_down_path\": 0, \"joined_segments\": 0,.*densified but the 0 whose ends the fixes alone join \\(--stand-down-path 0\\)" skeleton --tracks ${WORK}/fl_t.txt --stand-down-path -0 --out-vertices ${WORK}/fl_v0.txt --out-edges ${WORK}/fl_e0.txt --quiet)
expect(evaluate_stand_down_every_segment 0 "\"f_score\": 0\\.49" evaluate-map ${WORK}/fl_gv.txt ${WORK}/fl_ge.txt ${WORK}/fl_v0.txt ${WORK}/fl_e0.txt --quiet)
expect(skeleton_stand_down_path_bad 2 "--stand-down-path must be >= 0 and finite" skeleton --tracks ${DATA}/block_tracks.txt --stand-down-path -1 --out-vertices ${WORK}/t_v.txt --out-edges ${WORK}/t_e.txt --quiet)
expect(skeleton_stand_down_path_inf 2 "--stand-down-path must be a finite number, got .inf." skeleton --tracks ${DATA}/block_tracks.txt --stand-down-path inf --out-vertices ${WORK}/t_v.txt --out-edges ${WORK}/t_e.txt --quiet)
expect(skeleton_stand_down_path_points 2 "--stand-down-path, .* apply to --tracks only" skeleton --points ${DATA}/figure_eight.xyz --radius 0.6 --stand-down-path 2 --out-vertices ${WORK}/a --out-edges ${WORK}/b)
expect(skeleton_local_support_points 2 "--local-support, --min-local-support and --merge apply to --tracks only" skeleton --points ${DATA}/figure_eight.xyz --radius 0.6 --local-support 4 --out-vertices ${WORK}/a --out-edges ${WORK}/b)
expect(skeleton_segment_turn_bad 2 "--segment-turn-tolerance must be in \\[0, 180\\] degrees" skeleton --tracks ${DATA}/block_tracks.txt --segment-turn-tolerance 200 --out-vertices ${WORK}/t_v.txt --out-edges ${WORK}/t_e.txt --quiet)
expect(skeleton_lateral_density_default 0 "\"min_density\": 0.05, \"min_lateral_density\": 0.3, \"density_radius\": .*\"dropped_sparse\": [0-9]+, \"dropped_lateral\": [1-9][0-9]*," skeleton --tracks ${DATA}/block_tracks.txt --out-vertices ${WORK}/t_v.txt --out-edges ${WORK}/t_e.txt --quiet)
# dropped_sparse counts the relative-density filter's samples only (it printed the total of both filters).
expect(skeleton_sparse_density_off 0 "\"min_density\": 0, .*\"dropped\": [1-9][0-9]*, \"dropped_sparse\": 0, \"dropped_lateral\": [1-9][0-9]*," skeleton --tracks ${DATA}/block_tracks.txt --min-density 0 --out-vertices ${WORK}/t_v.txt --out-edges ${WORK}/t_e.txt --quiet)
expect(skeleton_lateral_density_off 0 "\"min_lateral_density\": 0, .*\"dropped_lateral\": 0," skeleton --tracks ${DATA}/block_tracks.txt --min-lateral-density 0 --out-vertices ${WORK}/t_v.txt --out-edges ${WORK}/t_e.txt --quiet)
expect(skeleton_lateral_density_bad 2 "--min-lateral-density must be in \\[0, 1\\]" skeleton --tracks ${DATA}/block_tracks.txt --min-lateral-density 1.5 --out-vertices ${WORK}/t_v.txt --out-edges ${WORK}/t_e.txt --quiet)
expect(skeleton_lateral_density_points 2 "--min-density, --min-lateral-density, --density-radius, .* apply to --tracks only" skeleton --points ${DATA}/figure_eight.xyz --radius 0.6 --min-lateral-density 0.2 --out-vertices ${WORK}/a --out-edges ${WORK}/b)
# Refusals of the lengths say what 0 and unset mean and give the value.
expect(skeleton_delta_negative 2 "--delta must be >= 0 \\(0: no simplification; unset: automatic\\), got '-1'" skeleton --points ${DATA}/figure_eight.xyz --radius 0.6 --delta -1 --out-vertices ${WORK}/a --out-edges ${WORK}/b)
expect(skeleton_repair_negative 2 "--repair must be >= 0 \\(0: no repair; unset: 0, or 2\\.5R with --tracks\\), got '-2'" skeleton --tracks ${DATA}/block_tracks.txt --repair -2 --out-vertices ${WORK}/a --out-edges ${WORK}/b)
expect(skeleton_prune_negative 2 "--prune must be >= 0 \\(0: keep all; unset: 0, or 5R with --tracks\\), got '-3'" skeleton --points ${DATA}/figure_eight.xyz --radius 0.6 --prune -3 --out-vertices ${WORK}/a --out-edges ${WORK}/b)
expect(skeleton_merge_negative 2 "--merge must be >= 0 \\(0: no merging; unset: 8 m\\), got '-1'" skeleton --tracks ${DATA}/block_tracks.txt --merge -1 --out-vertices ${WORK}/a --out-edges ${WORK}/b)
expect(skeleton_merge_points 2 "apply to --tracks only" skeleton --points ${DATA}/figure_eight.xyz --radius 0.6 --merge 5 --out-vertices ${WORK}/a --out-edges ${WORK}/b)
expect(skeleton_tracks_heading 2 "--heading-tolerance must be in \\[0, 180\\]" skeleton --tracks ${DATA}/block_tracks.txt --heading-tolerance 200 --out-vertices ${WORK}/a --out-edges ${WORK}/b)
expect(skeleton_tracks_density_heading 2 "--density-heading-tolerance must be in \\[0, 180\\]" skeleton --tracks ${DATA}/block_tracks.txt --density-heading-tolerance -5 --out-vertices ${WORK}/a --out-edges ${WORK}/b)
expect(skeleton_density_heading_points 2 "apply to --tracks only" skeleton --points ${DATA}/figure_eight.xyz --radius 0.6 --density-heading-tolerance 30 --out-vertices ${WORK}/a --out-edges ${WORK}/b)

# synthetic-city: an organic city (200 trips) written as tracks and ground truth; the road map the skeleton
# command builds from the tracks scores F = 0.81 against it (pinned at 0.80 or more); the same seed gives the
# same files; bad options are explained.
expect(synthetic_city 0 "\"layout\": \"organic\", \"intersections\": 48, .*\"trips\": 200, .*\"seed\": 5}" synthetic-city --layout organic --trips 200 --seed 5 --out-tracks ${WORK}/sc_t.txt --out-vertices ${WORK}/sc_gv.txt --out-edges ${WORK}/sc_ge.txt)
expect(synthetic_city_again 0 "\"seed\": 5}" synthetic-city --layout organic --trips 200 --seed 5 --out-tracks ${WORK}/sc_t2.txt --out-vertices ${WORK}/sc_gv2.txt --out-edges ${WORK}/sc_ge2.txt --out-streets-vertices ${WORK}/sc_sv.txt --out-streets-edges ${WORK}/sc_se.txt)
expect_same_file(${WORK}/sc_t.txt ${WORK}/sc_t2.txt "synthetic_city_again: tracks")
expect_same_file(${WORK}/sc_gv.txt ${WORK}/sc_gv2.txt "synthetic_city_again: truth vertices")
expect_same_file(${WORK}/sc_ge.txt ${WORK}/sc_ge2.txt "synthetic_city_again: truth edges")
expect_count(${WORK}/sc_t.txt "^# trip_id x y t" 1)
expect_count(${WORK}/sc_t.txt "\n200 " 0)
expect(synthetic_city_map 0 "\"components\": 1," skeleton --tracks ${WORK}/sc_t.txt --out-vertices ${WORK}/sc_v.txt --out-edges ${WORK}/sc_e.txt --quiet)
expect(synthetic_city_score 0 "\"f_score\": 0\\.[89][0-9]*," evaluate-map ${WORK}/sc_gv.txt ${WORK}/sc_ge.txt ${WORK}/sc_v.txt ${WORK}/sc_e.txt)
# The grid city recorded every 20 s: segments between fixes are checked against the other traces (F 0.76; 0.62
# with the check off, which densifies the corner cuts through the blocks). Random routes run straight while their
# segments cut blocks: straight segments are confirmed 198 times in 387, so the turn rule is not trusted (F 0.71
# with --straight-confirmed 0, which densifies the 189 unconfirmed straight ones). 542 segments longer than 80 m
# are confirmed at a local distance below 20 m where fixes are dense (--local-support): 63 confirmed at 20 m are
# not (F 0.764, 0.773 without the local check; with --local-support 0, 509 and 224 are confirmed as before). One unconfirmed straight
# segment has quiet ends (fewer than 4 fix positions within 20 m of each, --quiet-ends) and is used all the same.
expect(synthetic_city_sparse 0 "\"seed\": 5}" synthetic-city --trips 600 --interval 20 --seed 5 --out-tracks ${WORK}/sp_t.txt --out-vertices ${WORK}/sp_gv.txt --out-edges ${WORK}/sp_ge.txt)
expect(synthetic_city_sparse_map 0 "\"checked_segments\": 932, \"confirmed_segments\": 446, \"straight_checked\": 387, \"straight_confirmed\": 198, \"min_straight_confirmed_fraction\": 0.75, \"turn_rule_used\": false, \"straight_segments\": 1, \"linked_segments\": [0-9]+, \"all_segments_used\": false, \"min_confirmed_fraction\": 0.2, \"local_support\": 8, \"min_local_support\": 0.6, \"locally_checked\": 542, \"locally_rejected\": 63, \"quiet_ends\": 4, \"quiet_segments\": 1," skeleton --tracks ${WORK}/sp_t.txt --out-vertices ${WORK}/sp_v.txt --out-edges ${WORK}/sp_e.txt --quiet)
expect(synthetic_city_sparse_map_local_off 0 "\"confirmed_segments\": 509, \"straight_checked\": 387, \"straight_confirmed\": 224, .*\"local_support\": 0, \"min_local_support\": 0.6, \"locally_checked\": 0, \"locally_rejected\": 0," skeleton --tracks ${WORK}/sp_t.txt --local-support 0 --out-vertices ${WORK}/sp0_v.txt --out-edges ${WORK}/sp0_e.txt --quiet)
expect(skeleton_quiet_ends_bad 2 "--quiet-ends must be a whole number of fixes in \\[0, 1024\\]" skeleton --tracks ${WORK}/sp_t.txt --quiet-ends 2.5 --out-vertices ${WORK}/sp0_v.txt --out-edges ${WORK}/sp0_e.txt --quiet)
expect(skeleton_quiet_ends_points 2 "--quiet-ends, --local-support, --min-local-support and --merge apply to --tracks only" skeleton --points ${DATA}/figure_eight.xyz --radius 0.6 --quiet-ends 4 --out-vertices ${WORK}/a --out-edges ${WORK}/b)
expect(skeleton_local_support_bad 2 "--local-support must be a whole number of fixes in \\[0, 1024\\]" skeleton --tracks ${WORK}/sp_t.txt --local-support 2.5 --out-vertices ${WORK}/sp0_v.txt --out-edges ${WORK}/sp0_e.txt --quiet)
expect(skeleton_local_support_large 2 "--local-support must be a whole number" skeleton --tracks ${WORK}/sp_t.txt --local-support 1025 --out-vertices ${WORK}/sp0_v.txt --out-edges ${WORK}/sp0_e.txt --quiet)
expect(skeleton_min_local_support_bad 2 "--min-local-support must be in \\(0, 1\\]" skeleton --tracks ${WORK}/sp_t.txt --min-local-support 0 --out-vertices ${WORK}/sp0_v.txt --out-edges ${WORK}/sp0_e.txt --quiet)
expect(synthetic_city_sparse_score 0 "\"f_score\": 0\\.(7[5-9]|[89][0-9])[0-9]*," evaluate-map ${WORK}/sp_gv.txt ${WORK}/sp_ge.txt ${WORK}/sp_v.txt ${WORK}/sp_e.txt)

# The skeleton's other formats: GraphML, GeoJSON, PLY, SVG, with the right counts (two loops that share a
# down-fork and an up-fork: 4 nodes, 5 arcs once the spurs at the base point and the farthest point are trimmed).
expect(skeleton_formats 0 "\"nodes\": 4, \"arcs\": 5" skeleton --points ${DATA}/figure_eight.xyz --radius 0.6 --delta 1 --out-vertices ${WORK}/f_v.txt --out-edges ${WORK}/f_e.txt --graphml ${WORK}/f.graphml --geojson ${WORK}/f.geojson --ply ${WORK}/f.ply --svg ${WORK}/f.svg --quiet)
expect_count(${WORK}/f.graphml "<node id=" 4)
expect_count(${WORK}/f.graphml "<edge id=" 5)
expect_count(${WORK}/f.geojson "\"LineString\"" 5)
expect_count(${WORK}/f.geojson "\"Point\"" 4)
expect_count(${WORK}/f.svg "<polyline" 5)
expect_count(${WORK}/f.svg "<svg [^>]*viewBox=\"0 0 [0-9.]+ [0-9.]+\"" 1)  # scales where it is shown smaller
file(STRINGS ${WORK}/f.ply ply_header LIMIT_COUNT 10)
# Arcs share their nodes' vertices: one graph, V - E = components - loops = 1 - 2 (each polyline its own piece
# would give V - E = 5).
if(NOT ply_header MATCHES "element vertex ([0-9]+)")
  message(SEND_ERROR "PLY header: ${ply_header}")
endif()
set(ply_vertices ${CMAKE_MATCH_1})
if(NOT ply_header MATCHES "element edge ([0-9]+)")
  message(SEND_ERROR "PLY header: ${ply_header}")
endif()
math(EXPR ply_euler "${ply_vertices} - ${CMAKE_MATCH_1}")
if(NOT ply_euler EQUAL -1)
  message(SEND_ERROR "PLY of the figure eight: ${ply_vertices} vertices, ${CMAKE_MATCH_1} edges (V - E ${ply_euler}, not -1)")
endif()
# Input from a pipe (`--points <(command)`, /dev/stdin) is read, not taken for an empty file (seeking back over a
# byte-order mark failed on pipes).
execute_process(COMMAND ${CMAKE_COMMAND} -E cat ${DATA}/figure_eight.xyz
                COMMAND ${FEATURERECON} skeleton --points /dev/stdin --radius 0.6 --delta 1 --quiet
                        --out-vertices ${WORK}/pipe_v.txt --out-edges ${WORK}/pipe_e.txt
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0 OR NOT out MATCHES "\"nodes\": 4, \"arcs\": 5")
  message(SEND_ERROR "skeleton_pipe: exit ${rc}\n${out}${err}")
endif()
expect_same_file(${WORK}/f_v.txt ${WORK}/pipe_v.txt "skeleton_pipe: another map from the same points")
# A summary that cannot be written (a full disk) is an error, not a success.
if(EXISTS /dev/full)
  execute_process(COMMAND ${FEATURERECON} skeleton --points ${DATA}/figure_eight.xyz --radius 0.6 --quiet
                          --out-vertices ${WORK}/full_v.txt --out-edges ${WORK}/full_e.txt
                  OUTPUT_FILE /dev/full RESULT_VARIABLE rc ERROR_VARIABLE err)
  if(NOT rc EQUAL 1 OR NOT err MATCHES "writing standard output failed")
    message(SEND_ERROR "skeleton_stdout_full: exit ${rc}\n${err}")
  endif()
  execute_process(COMMAND ${FEATURERECON} skeleton --help OUTPUT_FILE /dev/full RESULT_VARIABLE rc ERROR_VARIABLE err)
  if(NOT rc EQUAL 1 OR NOT err MATCHES "featurerecon skeleton: error: writing standard output failed")
    message(SEND_ERROR "skeleton_help_full: exit ${rc}\n${err}")
  endif()
endif()
# Taubin rounds by default (the JSON names the method and the rounds); road maps use Laplacian rounds.
expect(skeleton_smoothing_default 0 "\"smoothing\": \"taubin\", \"smoothing_rounds\": 10," skeleton --points ${DATA}/figure_eight.xyz --radius 0.6 --out-vertices ${WORK}/a --out-edges ${WORK}/b --quiet)
expect(skeleton_smoothing_laplacian 0 "\"smoothing\": \"laplacian\", \"smoothing_rounds\": 3," skeleton --points ${DATA}/figure_eight.xyz --radius 0.6 --smoothing-method laplacian --smoothing 3 --out-vertices ${WORK}/a --out-edges ${WORK}/b --quiet)
expect(skeleton_smoothing_tracks 0 "\"smoothing\": \"laplacian\", \"smoothing_rounds\": 2," skeleton --tracks ${DATA}/block_tracks.txt --out-vertices ${WORK}/a --out-edges ${WORK}/b --quiet)

# Files in and out. A directory is not an input file (std::ifstream opens one and reads nothing).
file(MAKE_DIRECTORY ${WORK}/a_directory)
expect(input_directory 1 "a_directory: is a directory, not a file" skeleton --points ${WORK}/a_directory --radius 1 --out-vertices ${WORK}/a --out-edges ${WORK}/b)
expect(input_directory_map 1 "a_directory: is a directory" evaluate-map ${WORK}/a_directory ${WORK}/a_directory ${WORK}/a ${WORK}/b)
# Every output is checked before the work starts, and a failed run writes none of its files.
file(REMOVE ${WORK}/io_v.txt)
expect(output_directory_missing 2 "--out-edges: the directory .*/no_such_dir of .* does not exist" skeleton --points ${DATA}/figure_eight.xyz --radius 0.6 --out-vertices ${WORK}/io_v.txt --out-edges ${WORK}/no_such_dir/e.txt --quiet)
expect(output_is_directory 2 "--svg: .*a_directory is a directory" skeleton --points ${DATA}/figure_eight.xyz --radius 0.6 --out-vertices ${WORK}/io_v.txt --out-edges ${WORK}/io_e.txt --svg ${WORK}/a_directory --quiet)
expect(output_twice 2 "--out-edges: .*io_v.txt is also written by --out-vertices" skeleton --points ${DATA}/figure_eight.xyz --radius 0.6 --out-vertices ${WORK}/io_v.txt --out-edges ${WORK}/io_v.txt --quiet)
expect(output_empty_name 2 "option --out-vertices needs a value, got an empty one" skeleton --points ${DATA}/figure_eight.xyz --radius 0.6 --out-vertices= --out-edges ${WORK}/io_e.txt --quiet)
if(EXISTS ${WORK}/io_v.txt)
  message(SEND_ERROR "output checks: a vertices file was written by a run that failed")
endif()
expect(synthetic_city_output_missing 2 "--out-vertices: the directory" synthetic-city --out-tracks ${WORK}/io_t.txt --out-vertices ${WORK}/no_such_dir/v.txt --out-edges ${WORK}/io_e.txt)
if(EXISTS ${WORK}/io_t.txt)
  message(SEND_ERROR "synthetic_city_output_missing: the tracks file was written by a run that failed")
endif()
# Outputs go through temporaries of their own: a user's FILE.tmp survives, and no temporary is left behind.
file(WRITE ${WORK}/keep.tmp "precious\n")
expect(temporary_names 0 "\"vertices_file\": \".*/keep\"" skeleton --points ${DATA}/figure_eight.xyz --radius 0.6 --out-vertices ${WORK}/keep --out-edges ${WORK}/keep_e --quiet)
file(READ ${WORK}/keep.tmp kept)
if(NOT kept STREQUAL "precious\n")
  message(SEND_ERROR "temporary_names: ${WORK}/keep.tmp was overwritten or removed")
endif()
file(GLOB leftovers ${WORK}/.keep* ${WORK}/.io_*)
if(leftovers)
  message(SEND_ERROR "temporary files left behind: ${leftovers}")
endif()
# Names are JSON strings.
expect(json_file_name 0 "\"vertices_file\": \".*/q\\\\\"v.txt\"" skeleton --points ${DATA}/figure_eight.xyz --radius 0.6 --out-vertices ${WORK}/q\"v.txt --out-edges ${WORK}/q_e.txt --quiet)
# A value-taking option followed by another option lost its value.
expect(option_without_value 2 "option --radius needs a value, got the option '--out-vertices'" skeleton --points ${DATA}/figure_eight.xyz --radius --out-vertices ${WORK}/a --out-edges ${WORK}/b)
# Map ids are integers: 1.9 is not vertex 1, and ids above 2^53 stay apart.
file(WRITE ${WORK}/id_v.txt "9007199254740993,0,0\n9007199254740992,100,0\n")
file(WRITE ${WORK}/id_e.txt "1,9007199254740993,9007199254740992\n")
expect(map_large_ids 0 "\"ground_truth_edges\": 1," evaluate-map ${WORK}/id_v.txt ${WORK}/id_e.txt ${WORK}/id_v.txt ${WORK}/id_e.txt)
file(WRITE ${WORK}/id_e2.txt "1,9007199254740993.5,9007199254740992\n")
expect(map_fractional_id 1 "id_e2.txt:1: vertex id '9007199254740993.5' is at least 2\\^53 in decimal notation, which cannot be read exactly \\(write the integer without a point or exponent\\)" evaluate-map ${WORK}/id_v.txt ${WORK}/id_e2.txt ${WORK}/id_v.txt ${WORK}/id_e.txt)
# Coordinates are written with every bit: a skeleton 10^5 times smaller has the same vertices, scaled.
file(STRINGS ${DATA}/figure_eight.xyz eight_lines)
set(tiny "")
foreach(line IN LISTS eight_lines)
  if(line MATCHES "^([-0-9.e]+) ([-0-9.e]+)$")
    string(APPEND tiny "${CMAKE_MATCH_1}e-5 ${CMAKE_MATCH_2}e-5\n")
  endif()
endforeach()
file(WRITE ${WORK}/tiny_eight.xyz "${tiny}")
expect(tiny_coordinates 0 "\"loops\": 2, \"components\": 1," skeleton --points ${WORK}/tiny_eight.xyz --radius 0.6e-5 --delta 1e-5 --out-vertices ${WORK}/tiny_v.txt --out-edges ${WORK}/tiny_e.txt --quiet)
file(STRINGS ${WORK}/tiny_v.txt tiny_first LIMIT_COUNT 1)
if(NOT tiny_first MATCHES "^0,-?[0-9.]+e-0[5-9],-?[0-9.]+e-0[5-9]$")
  message(SEND_ERROR "tiny_coordinates: the first vertex lost its digits: '${tiny_first}'")
endif()
# Thinning probes 27 cells in any dimension (3^d before: 14-D points took 40 s).
set(d14 "")
# 100 points at least 1 apart, each given twice 0.1 apart (in the last coordinate): half of them go.
foreach(i RANGE 99)
  math(EXPR a "${i} % 7")
  math(EXPR b "${i} % 11")
  math(EXPR c "${i} % 13")
  string(APPEND d14 "0.${a} 0.${b} 0.${c} 0 0 0 0 0 0 0 0 0 0 ${i}\n0.${a} 0.${b} 0.${c} 0 0 0 0 0 0 0 0 0 0 ${i}.1\n")
endforeach()
file(WRITE ${WORK}/d14.xyz "${d14}")
expect(thinning_high_dimension 0 "\"points\": 200, \"sampled\": 100," skeleton --points ${WORK}/d14.xyz --radius 2 --sample-spacing 0.5 --out-vertices ${WORK}/a --out-edges ${WORK}/b --quiet)
# ... both limits included.
expect(evaluate_map_threshold_smallest 0 "\"precision\": 1, \"recall\": 1, \"f_score\": 1," evaluate-map ${WORK}/sk_v.txt ${WORK}/sk_e.txt ${WORK}/sk_v.txt ${WORK}/sk_e.txt --threshold 3.4395525670743494e-136)
expect(evaluate_map_threshold_largest 0 "\"precision\": 1, \"recall\": 1, \"f_score\": 1," evaluate-map ${WORK}/sk_v.txt ${WORK}/sk_e.txt ${WORK}/sk_v.txt ${WORK}/sk_e.txt --threshold 2.9073548971824276e135)
# Thinning at extreme scales: squares of distances underflowed (copies kept at a spacing of 1e-200) or overflowed
# (points 1e185 apart kept at 1e190).
file(WRITE ${WORK}/thin_dup.xyz "1 1\n1 1\n1 1\n2 2\n")
expect(thinning_tiny_spacing 0 "\"points\": 4, \"sampled\": 2," skeleton --points ${WORK}/thin_dup.xyz --radius 1e-150 --sample-spacing 1e-200 --out-vertices ${WORK}/a --out-edges ${WORK}/b --quiet)
file(WRITE ${WORK}/thin_big.xyz "0 0\n1e185 0\n")
expect(thinning_huge_spacing 0 "\"points\": 2, \"sampled\": 1," skeleton --points ${WORK}/thin_big.xyz --radius 1e190 --sample-spacing 1e190 --out-vertices ${WORK}/a --out-edges ${WORK}/b --quiet)
# One file spelt two ways is still one file.
expect(output_twice_spelt_differently 2 "--out-edges: .*/\\./io_v.txt is also written by --out-vertices" skeleton --points ${DATA}/figure_eight.xyz --radius 0.6 --out-vertices ${WORK}/io_v.txt --out-edges ${WORK}/./io_v.txt --quiet)
# Pictures as PNG: the same drawing rasterised.
expect(skeleton_png 0 "\"loops\": 2," skeleton --points ${DATA}/figure_eight.xyz --radius 0.6 --delta 1 --out-vertices ${WORK}/png_v.txt --out-edges ${WORK}/png_e.txt --svg ${WORK}/skeleton.png --quiet)
file(READ ${WORK}/skeleton.png png_magic LIMIT 8 HEX)
if(NOT png_magic STREQUAL "89504e470d0a1a0a")
  message(SEND_ERROR "skeleton_png: ${WORK}/skeleton.png is not a PNG file (starts ${png_magic})")
endif()
expect(evaluate_map_png 0 "\"f_score\": 1," evaluate-map ${WORK}/png_v.txt ${WORK}/png_e.txt ${WORK}/png_v.txt ${WORK}/png_e.txt --threshold 0.5 --interval 0.1 --svg ${WORK}/match.png)
file(READ ${WORK}/match.png png_magic LIMIT 8 HEX)
if(NOT png_magic STREQUAL "89504e470d0a1a0a")
  message(SEND_ERROR "evaluate_map_png: ${WORK}/match.png is not a PNG file")
endif()
expect(skeleton_picture_extension 2 "--svg writes a picture: give a file ending in .svg, .png" skeleton --points ${DATA}/figure_eight.xyz --radius 0.6 --out-vertices ${WORK}/a --out-edges ${WORK}/b --svg ${WORK}/p.txt)
# A picture of points spanning more than the largest double (from -1e308 to 1e308) is still drawn.
set(far "")
foreach(i RANGE 19)
  string(APPEND far "1e308 0.${i}\n-1e308 0.${i}\n")
endforeach()
file(WRITE ${WORK}/far.xyz "${far}")
expect(picture_of_huge_extent 0 "\"components\": 2" skeleton --points ${WORK}/far.xyz --radius 0.3 --out-vertices ${WORK}/far_v.txt --out-edges ${WORK}/far_e.txt --svg ${WORK}/far.svg --quiet)
file(READ ${WORK}/far.svg far_svg)
if(far_svg MATCHES "nan|inf")
  message(SEND_ERROR "picture_of_huge_extent: ${WORK}/far.svg has a non-finite coordinate")
endif()
# A write that fails half-way (here the file size limit of `ulimit -f`, as on a full disk) is reported with the
# file the user named, not the temporary it was written through (Outputs::name_targets); the file the user had
# there stays as it was, and no temporary is left behind. Text and PNG writers.
if(BASH_PROGRAM)
  file(MAKE_DIRECTORY ${WORK}/limited)
  file(WRITE ${WORK}/limited/big.txt "old complex\n")
  file(WRITE ${WORK}/limited/match.png "old picture\n")
  foreach(case "rips;big.txt;write failed" "evaluate-map;match.png;cannot write PNG")
    list(GET case 0 command)
    list(GET case 1 target)
    list(GET case 2 reason)
    if(command STREQUAL "rips")
      set(arguments rips --points ${DATA}/figure_eight.xyz --radius 0.6 --out ${WORK}/limited/${target} --quiet)
    else()
      set(maps ${DATA}/chicago_maps)
      set(arguments evaluate-map ${maps}/chicago_gt_trk25_vertices.txt ${maps}/chicago_gt_trk25_edges.txt
          ${maps}/chicago_gt_crp_vertices.txt ${maps}/chicago_gt_crp_edges.txt --svg ${WORK}/limited/${target})
    endif()
    execute_process(COMMAND ${BASH_PROGRAM} -c "trap '' XFSZ; ulimit -f 4; exec \"$0\" \"$@\"" ${FEATURERECON}
                    ${arguments} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
    string(REPLACE "." "\\." escaped ${target})
    if(NOT rc EQUAL 1 OR NOT err MATCHES "limited/${escaped}: ${reason}" OR err MATCHES "\\.${escaped}\\.")
      message(SEND_ERROR "write_failure_${command}: exit ${rc}, expected 1 and an error naming ${target}:\n${out}${err}")
    else()
      message(STATUS "ok: write_failure_${command}")
    endif()
  endforeach()
  file(READ ${WORK}/limited/big.txt kept_complex)
  file(READ ${WORK}/limited/match.png kept_picture)
  if(NOT kept_complex STREQUAL "old complex\n" OR NOT kept_picture STREQUAL "old picture\n")
    message(SEND_ERROR "write_failure: a file the user had was changed by a failed write")
  endif()
  file(GLOB leftovers ${WORK}/limited/.*)
  if(leftovers)
    message(SEND_ERROR "write_failure: temporary files left behind: ${leftovers}")
  endif()
endif()
# skeleton --image: a pixel is ink when darker than T (default 128) or, with --ink bright, at least T; T is a
# grey level in [1, 255]. Grey levels 127, 128, 255: one dark pixel (127), two bright ones (128 and 255).
file(WRITE ${A}/grey3.pgm "P2\n3 1\n255\n127 128 255\n")
# Audit of the command line (mutation testing of src/cli): each audit_ test pins a property the help or the
# README promises that no earlier test checked.
expect(audit_image_dark_default 0 "\"points\": 1, .*\"ink\": \"dark\", \"ink_threshold\": 128" skeleton --image ${A}/grey3.pgm --out-vertices ${A}/v.txt --out-edges ${A}/e.txt --quiet)
expect_count(${A}/v.txt "^0,0\\.5,0\\.5\n$" 1)
expect(audit_image_bright_default 0 "\"points\": 2, .*\"ink\": \"bright\", \"ink_threshold\": 128" skeleton --image ${A}/grey3.pgm --ink bright --out-vertices ${A}/v.txt --out-edges ${A}/e.txt --quiet)
expect(audit_image_threshold_range 2 "--ink-threshold must be an integer grey level in \\[1, 255\\], got '256'" skeleton --image ${A}/grey3.pgm --ink-threshold 256 --out-vertices ${A}/v.txt --out-edges ${A}/e.txt)
# --max-triangles: default 2^27, printed in the skeleton's JSON.
expect(audit_skeleton_max_triangles_default 0 "\"max_triangles\": 134217728," skeleton --points ${DATA}/figure_eight.xyz --radius 0.6 --out-vertices ${A}/v.txt --out-edges ${A}/e.txt --quiet)
# skeleton: 0 is allowed for --delta (no simplification), --repair (no repair) and --prune (keep all); a negative
# --sample-spacing and --smoothing are refused; --picture-size takes 100 (its least).
expect(audit_skeleton_zero_lengths 0 "\"delta\": 0, \"repair\": 0, .*\"prune\": 0," skeleton --points ${DATA}/figure_eight.xyz --radius 0.6 --delta 0 --repair 0 --prune 0 --out-vertices ${A}/v.txt --out-edges ${A}/e.txt --quiet)
expect(audit_skeleton_spacing_negative 2 "--sample-spacing must be >= 0 \\(0: no thinning\\)" skeleton --points ${DATA}/figure_eight.xyz --radius 0.6 --sample-spacing -1 --out-vertices ${A}/v.txt --out-edges ${A}/e.txt)
expect(audit_skeleton_smoothing_negative 2 "--smoothing must be an integer in \\[0, 1000000\\], got -1" skeleton --points ${DATA}/figure_eight.xyz --radius 0.6 --smoothing -1 --out-vertices ${A}/v.txt --out-edges ${A}/e.txt)
expect(audit_skeleton_picture_size_least 0 "\"loops\": 2," skeleton --points ${DATA}/figure_eight.xyz --radius 0.6 --delta 1 --svg ${A}/p.svg --picture-size 100 --out-vertices ${A}/v.txt --out-edges ${A}/e.txt --quiet)
# Thinning keeps a point unless a kept point is closer than S: two points exactly S apart both stay.
file(WRITE ${A}/two.xyz "0 0\n1 0\n")
expect(audit_thinning_at_spacing 0 "\"points\": 2, \"sampled\": 2," skeleton --points ${A}/two.xyz --radius 2 --sample-spacing 1 --out-vertices ${A}/v.txt --out-edges ${A}/e.txt --quiet)
# The spacing warning gives the median of the nearest-neighbour distances: 1, 1, 2, 4 have the median 2 (the
# upper of the two middle values); it is for fewer than one neighbour per point (two pairs: one each, no warning).
file(WRITE ${A}/line4.xyz "0 0\n1 0\n3 0\n7 0\n")
expect(audit_spacing_median 0 "the median distance from a point to its nearest neighbour is 2: give --radius above it" skeleton --points ${A}/line4.xyz --radius 0.5 --out-vertices ${A}/v.txt --out-edges ${A}/e.txt --quiet)
file(WRITE ${A}/pairs.xyz "0 0\n0.1 0\n5 0\n5.1 0\n")
expect(audit_spacing_pairs 0 "\"rips_edges\": 2," skeleton --points ${A}/pairs.xyz --radius 0.2 --out-vertices ${A}/v.txt --out-edges ${A}/e.txt --quiet)
if(last_error MATCHES "warning")
  message(SEND_ERROR "audit_spacing_pairs: a warning although every point has a neighbour:\n${last_error}")
endif()
# --sample-spacing does not apply to a graph or a distance matrix; a distance matrix has zeros on its diagonal and
# no negative entries.
expect(audit_graph_spacing 2 "--sample-spacing applies to --points, --image and --tracks only" skeleton --graph ${DATA}/figure_eight_graph.txt --sample-spacing 1 --out-vertices ${A}/v.txt --out-edges ${A}/e.txt)
file(WRITE ${A}/diagonal.txt "0 1\n1 2\n")
expect(audit_matrix_diagonal 1 "diagonal.txt:2: the diagonal entry of row 1 is not 0" skeleton --distance-matrix ${A}/diagonal.txt --radius 1 --out-vertices ${A}/v.txt --out-edges ${A}/e.txt)
file(WRITE ${A}/negative.txt "0 -1\n-1 0\n")
expect(audit_matrix_negative 1 "negative.txt:1: negative distance in column 1 of row 0" skeleton --distance-matrix ${A}/negative.txt --radius 1 --out-vertices ${A}/v.txt --out-edges ${A}/e.txt)
# --graph: no radius (null in the JSON); edge lengths are 3-D (an edge along z, 5 long, gives the level width 5).
file(WRITE ${A}/z_graph.txt "2 1\n0 0 0 0\n0 0 5 1\n0 1\n")
expect(audit_graph_z 0 "\"radius\": null, .*\"level_width\": 5," skeleton --graph ${A}/z_graph.txt --out-vertices ${A}/v.txt --out-edges ${A}/e.txt --quiet)
# Tracks: the angles are in [0, 180] degrees and the densities in [0, 1].
expect(audit_tracks_heading_negative 2 "--heading-tolerance must be in \\[0, 180\\]" skeleton --tracks ${DATA}/block_tracks.txt --heading-tolerance -5 --out-vertices ${A}/v.txt --out-edges ${A}/e.txt)
expect(audit_tracks_density_heading_large 2 "--density-heading-tolerance must be in \\[0, 180\\]" skeleton --tracks ${DATA}/block_tracks.txt --density-heading-tolerance 200 --out-vertices ${A}/v.txt --out-edges ${A}/e.txt)
expect(audit_tracks_min_density_large 2 "--min-density must be in \\[0, 1\\]" skeleton --tracks ${DATA}/block_tracks.txt --min-density 1.5 --out-vertices ${A}/v.txt --out-edges ${A}/e.txt)
# Few fixes a trip: the warning is for fewer than two fixes a trip on average, and for several trips.
file(WRITE ${A}/two_a_trip.txt "0 0 0 0\n0 10 0 1\n1 0 5 0\n1 10 5 1\n")
expect(audit_two_fixes_a_trip 0 "\"trips\": 2," skeleton --tracks ${A}/two_a_trip.txt --out-vertices ${A}/v.txt --out-edges ${A}/e.txt --quiet)
if(last_error MATCHES "fewer than two a trip")
  message(SEND_ERROR "audit_two_fixes_a_trip: warned although every trip has two fixes:\n${last_error}")
endif()
file(WRITE ${A}/one_fix.txt "0 0 0 0\n")
expect(audit_one_fix 0 "\"trips\": 1," skeleton --tracks ${A}/one_fix.txt --out-vertices ${A}/v.txt --out-edges ${A}/e.txt --quiet)
if(last_error MATCHES "fewer than two a trip")
  message(SEND_ERROR "audit_one_fix: warned for a single trip:\n${last_error}")
endif()
# Degrees read as metres: a median step below 0.01 with every fix within +-180 and +-90 is refused (steps of 0.005
# degrees, about 500 m); y up to 100 is no latitude (not refused).
file(WRITE ${A}/deg_tracks.txt "0 10 50 0\n0 10.005 50 10\n0 10.01 50 20\n")
expect(audit_degree_tracks 1 "deg_tracks.txt: the fixes look like longitude and latitude in degrees \\(median step 0.005" skeleton --tracks ${A}/deg_tracks.txt --out-vertices ${A}/v.txt --out-edges ${A}/e.txt)
file(WRITE ${A}/not_deg_tracks.txt "0 10 100 0\n0 10.005 100 10\n0 10.01 100 20\n")
expect(audit_not_degree_tracks 0 "\"trips\": 1," skeleton --tracks ${A}/not_deg_tracks.txt --out-vertices ${A}/v.txt --out-edges ${A}/e.txt --quiet)
file(WRITE ${A}/deg_v.txt "0,10,50\n1,10.005,50\n")
file(WRITE ${A}/deg_e.txt "0,0,1\n")
expect(audit_degree_map 1 "deg_v.txt: the vertices look like longitude and latitude in degrees \\(median edge 0.005" evaluate-map ${A}/deg_v.txt ${A}/deg_e.txt ${A}/deg_v.txt ${A}/deg_e.txt)
file(WRITE ${A}/not_deg_v.txt "0,10,100\n1,10.005,100\n")
expect(audit_not_degree_map 0 "\"f_score\": " evaluate-map ${A}/not_deg_v.txt ${A}/deg_e.txt ${A}/not_deg_v.txt ${A}/deg_e.txt --threshold 0.001 --interval 0.001)
# File names are JSON strings: a control character (a tab) is escaped.
expect(audit_json_tab 0 "\"vertices_file\": \"[^\"]*tab\\\\u0009v\\.txt\"" skeleton --points ${DATA}/figure_eight.xyz --radius 0.6 --out-vertices "${A}/tab\tv.txt" --out-edges ${A}/e.txt --quiet)
# The picture of a --graph skeleton has 3 pixels per level width (help of --svg): a chain of 499 unit edges is
# 1497 pixels long, plus the margins.
set(audit_chain "500 499\n")
foreach(i RANGE 499)
  string(APPEND audit_chain "${i} 0 0 0\n")
endforeach()
foreach(i RANGE 498)
  math(EXPR j "${i} + 1")
  string(APPEND audit_chain "${i} ${j}\n")
endforeach()
file(WRITE ${A}/chain.txt "${audit_chain}")
expect(audit_graph_picture_scale 0 "\"level_width\": 1," skeleton --graph ${A}/chain.txt --out-vertices ${A}/v.txt --out-edges ${A}/e.txt --svg ${A}/chain.svg --quiet)
expect_count(${A}/chain.svg "viewBox=\"0 0 1517\\.00 20\\.00\"" 1)
# A radius derived from the data is held to the limit of --radius (1e300), as the message says.
file(WRITE ${A}/far2.xyz "0 0\n1e301 0\n")
expect(audit_estimated_radius_huge 1 "far2.xyz: the radius derived from the data, 1\\.60726e\\+301, exceeds 1e300 .*give --radius" skeleton --points ${A}/far2.xyz --out-vertices ${A}/v.txt --out-edges ${A}/e.txt)

# A tracks file that fails on its first line says what it may be instead: gzip-compressed, comma-separated, or
# with a header line that lacks its '#' (each error named only the line and the count or the token).
expect(tracks_gzip 1 "tracks.txt.gz:1: expected 'trip_id x y \\[t\\]', got [0-9]+ values \\(the file is gzip-compressed: decompress it first" skeleton --tracks ${PROJECT_DATA}/gps/chicago/tracks.txt.gz --out-vertices ${WORK}/g_v.txt --out-edges ${WORK}/g_e.txt)
file(WRITE ${WORK}/commas.txt "0,1,2,3\n0,4,5,6\n")
expect(tracks_commas 1 "commas.txt:1: expected 'trip_id x y \\[t\\]', got 1 values \\(values are separated by spaces or tabs, not by commas" skeleton --tracks ${WORK}/commas.txt --out-vertices ${WORK}/g_v.txt --out-edges ${WORK}/g_e.txt)
file(WRITE ${WORK}/header.txt "# a comment\ntrip_id x y t\n0 1 2 3\n0 4 5 6\n")
expect(tracks_header 1 "header.txt:2: 'x' is not a number \\(x\\) \\(a header line must begin with '#'\\)" skeleton --tracks ${WORK}/header.txt --out-vertices ${WORK}/g_v.txt --out-edges ${WORK}/g_e.txt)
file(WRITE ${WORK}/bad_later.txt "0 1 2 3\n0 4 5\n")
expect(tracks_no_hint 1 "bad_later.txt:2: no time t, but the first line has one \\('trip_id x y t'\\)\n" skeleton --tracks ${WORK}/bad_later.txt --out-vertices ${WORK}/g_v.txt --out-edges ${WORK}/g_e.txt)

# Two vehicles 500 m apart under one trip id, fixes interleaved in time: the median speed between
# consecutive fixes is 1,000 m/s, and the command says what may be wrong (no such warning on real traces
# above, nor on a file without times, whose times are line numbers).
set(shared "")
set(shared_untimed "")
foreach(i RANGE 11)
  math(EXPR xa "10 * ${i}")
  math(EXPR xb "500 + 10 * ${i}")
  string(APPEND shared "0 ${xa} 0 ${i}\n0 ${xb} 0 ${i}.5\n")
  string(APPEND shared_untimed "0 ${xa} 0\n0 ${xb} 0\n")
endforeach()
file(WRITE ${WORK}/shared_id.txt "${shared}")
expect(tracks_shared_id 0 "warning: .*shared_id.txt: the median speed between consecutive fixes of a trip is 1000 m/s \\(3600 km/h\\): do several vehicles share a trip id" skeleton --tracks ${WORK}/shared_id.txt --out-vertices ${WORK}/s_v.txt --out-edges ${WORK}/s_e.txt --quiet)
file(WRITE ${WORK}/shared_untimed.txt "${shared_untimed}")
expect(tracks_shared_id_untimed 0 "\"trips\": 1," skeleton --tracks ${WORK}/shared_untimed.txt --out-vertices ${WORK}/s_v.txt --out-edges ${WORK}/s_e.txt --quiet)
if(last_error MATCHES "median speed")
  message(SEND_ERROR "tracks_shared_id_untimed: a speed warning for a file without times:\n${last_error}")
endif()
expect(tracks_block_no_speed_warning 0 "\"trips\": " skeleton --tracks ${DATA}/block_tracks.txt --out-vertices ${WORK}/s_v.txt --out-edges ${WORK}/s_e.txt --quiet)
if(last_error MATCHES "median speed")
  message(SEND_ERROR "tracks_block_no_speed_warning: a speed warning on ordinary traces:\n${last_error}")
endif()

# Review of the warnings above. Tracks in degrees are refused whatever their stays: 3 trips at 1 Hz (steps of
# 1e-4 degrees, every fix "within 20" of the others: stays by the 20 m / 30 s rule) beside 4 trips every
# 120 s (steps of 0.02): the median over moving vehicles was 0.02 and the file ran as metres.
set(degrees "")
foreach(t RANGE 2)
  foreach(i RANGE 39)
    set(ii "${i}")
    if(i LESS 10)
      set(ii "0${i}")
    endif()
    string(APPEND degrees "a${t} -87.6${t}${ii} 41.8 ${i}\n")
  endforeach()
endforeach()
foreach(t RANGE 3)
  foreach(i RANGE 2)
    math(EXPR s "120 * ${i}")
    string(APPEND degrees "b${t} -87.${t}${i} 41.9 ${s}\n")
  endforeach()
endforeach()
file(WRITE ${WORK}/degrees_mixed.txt "${degrees}")
expect(tracks_degrees_with_stays 1 "degrees_mixed.txt: the fixes look like longitude and latitude in degrees" skeleton --tracks ${WORK}/degrees_mixed.txt --out-vertices ${WORK}/s_v.txt --out-edges ${WORK}/s_e.txt --quiet)
# A comma in a comment is no sign of comma-separated values (the hint reads the failing row's tokens).
file(WRITE ${WORK}/comment_commas.txt "0 1 2 3 4 # id, x, y, t, speed\n")
expect(tracks_comment_commas 1 "comment_commas.txt:1: expected 'trip_id x y \\[t\\]', got 5 values\n" skeleton --tracks ${WORK}/comment_commas.txt --out-vertices ${WORK}/s_v.txt --out-edges ${WORK}/s_e.txt)
# A directory of one timed trip (10 m/s) and three without times (100 m a line): only the timed trip is
# judged, and it is slow.
file(MAKE_DIRECTORY ${WORK}/mixed_trips)
set(timed "")
set(untimed "")
foreach(i RANGE 20)
  math(EXPR x "10 * ${i}")
  math(EXPR y "100 * ${i}")
  string(APPEND timed "${x} 0 ${i}\n")
  string(APPEND untimed "0 ${y}\n")
endforeach()
file(WRITE ${WORK}/mixed_trips/trip_0.txt "${timed}")
foreach(t 1 2 3)
  file(WRITE ${WORK}/mixed_trips/trip_${t}.txt "${untimed}")
endforeach()
expect(tracks_mixed_directory 0 "\"trips\": 4," skeleton --tracks ${WORK}/mixed_trips --out-vertices ${WORK}/s_v.txt --out-edges ${WORK}/s_e.txt --quiet)
if(last_error MATCHES "median speed")
  message(SEND_ERROR "tracks_mixed_directory: a speed warning from trips without times:\n${last_error}")
endif()
