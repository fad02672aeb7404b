# SPDX-License-Identifier: GPL-3.0-or-later
# Point clouds: sample (darts, elimination, bilateral, --periodic) and sample-stats (spacing, the domain,
# the spectrum), the cloud readers (XYZ, OFF, PLY).
# Run by ctest as cli_sample with the variables of cli_common.cmake.
include(${CMAKE_CURRENT_LIST_DIR}/cli_common.cmake)

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
file(WRITE ${WORK}/bad.xyz.txt "0 0 0 1\n")
expect(sample_bad_format 1 "bad.xyz.txt: expected 2 numbers per line \\(points in the plane\\), 3 \\(a cloud\\) or 6 \\(a cloud with normals\\), got 4" sample --input ${WORK}/bad.xyz.txt --count 1 --out ${WORK}/s.xyz)
# A file that is not text points and not a cloud format: said to have been read as text.
file(WRITE ${WORK}/mesh.obj "v 0 0 0\nv 1 0 0\nf 1 2 3\n")
expect(sample_obj_read_as_text 1 "mesh.obj:1: 'v' is not a number \\(coordinate\\) \\(a file ending in .obj is read as text: 2 or 3 numbers per line, or 6 with normals; point clouds are PLY, OFF or XYZ\\)" sample --input ${WORK}/mesh.obj --count 1 --out ${WORK}/s.xyz)
expect(sample_stats_obj_read_as_text 1 "a file ending in .obj is read as text" sample-stats --input ${WORK}/mesh.obj)
# ... but a missing file is only missing.
expect(sample_missing_obj 1 "missing.obj: cannot open for reading \\(No such file or directory\\)\n" sample --input ${WORK}/missing.obj --count 1 --out ${WORK}/s.xyz)
file(WRITE ${WORK}/no_points.txt "# nothing\n")
expect(sample_no_points 2 "--count 1 exceeds the 0 points of .*no_points.txt" sample --input ${WORK}/no_points.txt --count 1 --out ${WORK}/s.txt)
expect(sample_no_points_radius 0 "\"kept\": 0,.*no_points.txt holds no points: the sample is empty" sample --input ${WORK}/no_points.txt --method darts --radius 0.1 --out ${WORK}/s.txt --quiet)
# Points in the plane (lines 'x y'): 1500 candidates of a linear congruential generator in the unit square,
# sampled on the unit torus (--periodic) and written as lines 'x y' that sample-stats reads.
# random_points(FILE SEED WIDTH): 1500 lines 'x y' of a linear congruential generator from SEED, six digits
# each, x in [0, WIDTH) (the integer part cycling through 0 .. WIDTH - 1), y in [0, 1).
function(random_points file seed width)
  set(lines "")
  set(v ${seed})
  foreach(i RANGE 1499)
    foreach(axis x y)
      math(EXPR v "(1103515245 * ${v} + 12345) % 2147483648")
      math(EXPR d "(${v} / 2048) % 1000000 + 1000000")
      string(SUBSTRING "${d}" 1 6 ${axis})
    endforeach()
    math(EXPR whole "${i} % ${width}")
    string(APPEND lines "${whole}.${x} 0.${y}\n")
  endforeach()
  file(WRITE ${file} "${lines}")
endfunction()
random_points(${WORK}/candidates.txt 12345 1)
expect(sample_plane_periodic 0 "\"kept\": 300,.*\"dimension\": 2, \"periodic\": true, .*\"domain_measure\": 1, \"relative_radius\": 0\\.[6-9]" sample --input ${WORK}/candidates.txt --count 300 --periodic --out ${WORK}/tile.txt --quiet)
expect_count(${WORK}/tile.txt "0\\.[0-9]+ 0\\.[0-9]+\n" 300)
expect(sample_plane_periodic_stats 0 "\"samples\": 300,.*\"periodic\": true,.*\"relative_radius\": 0\\.[6-9].*\"effective_nyquist\": " sample-stats --input ${WORK}/tile.txt --periodic --quiet)
expect(sample_plane_darts 0 "\"kept\": 100, \"method\": \"darts\",.*\"periodic\": true" sample --input ${WORK}/candidates.txt --count 100 --method darts --periodic --out ${WORK}/darts_tile.txt --quiet)
expect(sample_plane_not_periodic 0 "\"kept\": 300,.*\"periodic\": false,.*\"relative_radius\": 0\\.[6-9]" sample --input ${WORK}/candidates.txt --count 300 --out ${WORK}/plain.txt --quiet)
expect(sample_plane_out_cloud 2 "candidates.txt holds points in the plane \\(2 numbers per line\\), written as lines 'x y': give --out FILE.txt" sample --input ${WORK}/candidates.txt --count 3 --out ${WORK}/s.xyz)
expect(sample_plane_sigma_feature 2 "--sigma-feature needs normals, which points in the plane" sample --input ${WORK}/candidates.txt --count 3 --sigma-feature 1 --out ${WORK}/s.txt)
expect(sample_cloud_out_text 2 "wall.xyz is a point cloud, written as PLY, OFF or XYZ" sample --input ${WORK}/wall.xyz --count 3 --out ${WORK}/s.txt)
# A cloud on the unit torus of space: the domain is the cube of measure 1, a volume.
expect(sample_cloud_periodic 0 "\"kept\": 100,.*\"dimension\": 3, \"periodic\": true, \"period\": null, \"intrinsic_dimension\": 3, \"domain_measure\": 1," sample --input ${WORK}/wall_plain.xyz --count 100 --periodic --out ${WORK}/wall_tile.xyz --quiet)
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
expect_same_file(${WORK}/bilateral.xyz ${WORK}/bilateral2.xyz "sample: the same seed gave different output")
expect(sample_ply 0 "\"kept\": 50" sample --input ${WORK}/wall.xyz --count 50 --out ${WORK}/s.ply --quiet)
expect_count(${WORK}/s.ply "property double nx" 1)
expect(sample_off 0 "\"kept\": 50" sample --input ${WORK}/wall.xyz --count 50 --out ${WORK}/s.off --quiet)
expect(sample_darts 0 "\"method\": \"darts\"" sample --input ${WORK}/wall.xyz --radius 2.5 --method darts --out ${WORK}/d.xyz --quiet)
expect(sample_darts_count 0 "\"kept\": 60,.*\"method\": \"darts\"" sample --input ${WORK}/wall.xyz --count 60 --method darts --out ${WORK}/d.xyz --quiet)
# No normals in the file: estimated when the bilateral distance needs them.
expect(sample_estimate 0 "\"normals\": \"estimated\"" sample --input ${WORK}/wall_plain.xyz --count 100 --sigma-feature 0.5 --unoriented --out ${WORK}/e.xyz --quiet)
# The estimate reports its progress (CGAL's callback): without --quiet its stage is announced on stderr (the
# line a pipe gets) and ends with its "done" line.
expect(sample_estimate_progress 0 "\"normals\": \"estimated\"" sample --input ${WORK}/wall_plain.xyz --count 100 --sigma-feature 0.5 --unoriented --out ${WORK}/e.xyz)
if(NOT last_error MATCHES "estimating normals \\.\\.\\.\n(.*\n)?estimating normals: done")
  message(SEND_ERROR "sample_estimate_progress: no progress of the normal estimation:\n${last_error}")
endif()
# Copies of a point (merged scans): the normal fit runs on the distinct positions (30 copies among the points, or a
# file of copies only, crashed the jet fit).
file(READ ${WORK}/wall_plain.xyz wall_with_copies)
foreach(i RANGE 29)
  string(APPEND wall_with_copies "0.5 0.5 0.05\n")
endforeach()
file(WRITE ${WORK}/wall_copies.xyz "${wall_with_copies}")
expect(sample_estimate_copies 0 "\"normals\": \"estimated\"" sample --input ${WORK}/wall_copies.xyz --count 20 --sigma-feature 0.5 --out ${WORK}/e.xyz --quiet)
file(WRITE ${WORK}/copies_only.xyz "1 2 3\n1 2 3\n1 2 3\n1 2 3\n1 2 3\n1 2 3\n1 2 3\n1 2 3\n1 2 3\n1 2 3\n1 2 3\n1 2 3\n1 2 3\n1 2 3\n1 2 3\n1 2 3\n1 2 3\n1 2 3\n1 2 3\n1 2 3\n")
expect(sample_estimate_copies_only 0 "\"kept\": 1,.*\"normals\": \"estimated\"" sample --input ${WORK}/copies_only.xyz --count 1 --sigma-feature 0.5 --out ${WORK}/e.xyz --quiet)
expect(sample_stats 0 "\"samples\": 200,.*\"relative_radius\": " sample-stats --input ${WORK}/euclid.xyz)
expect(sample_stats_2d 0 "\"dimension\": 2,.*\"average_minimum_distance\": " sample-stats --input ${DATA}/figure_eight.xyz)
expect(sample_stats_bad 2 "--intrinsic-dimension must be 2 or 3" sample-stats --input ${DATA}/figure_eight.xyz --intrinsic-dimension 4)
file(WRITE ${WORK}/plane3.txt "0 0\n1 0\n0 1\n")
expect(sample_stats_dimension_above_points 2 "--intrinsic-dimension 3 exceeds the dimension of the points of .*plane3.txt \\(2\\)" sample-stats --input ${WORK}/plane3.txt --intrinsic-dimension 3)
# Estimated from the samples alone, the dimension and measure can differ from what `sample` printed: said so.
expect(sample_stats_estimate_note 0 "\"samples\": 200,.*note: intrinsic dimension [23] and domain measure estimated from the 200 samples alone" sample-stats --input ${WORK}/euclid.xyz)
expect(sample_stats_given_no_note 0 "\"intrinsic_dimension\": 2," sample-stats --input ${WORK}/euclid.xyz --intrinsic-dimension 2)
if(last_error MATCHES "note:")
  message(SEND_ERROR "sample_stats_given_no_note: a note although the dimension was given:\n${last_error}")
endif()
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
# The sums' method: the non-uniform FFT by default for 256 samples at F = 96, the direct sums on request; the
# library's tests compare the two.
expect(sample_stats_spectrum_gridded 0 "\"spectrum_method\": \"gridded\"" sample-stats --input ${WORK}/torus.txt --periodic --quiet)
expect(sample_stats_spectrum_direct 0 "\"spectrum_method\": \"direct\"" sample-stats --input ${WORK}/torus.txt --periodic --spectrum-method direct --quiet)
expect(sample_stats_spectrum_bad_method 2 "--spectrum-method must be automatic, gridded or direct, got 'fft'" sample-stats --input ${WORK}/torus.txt --periodic --spectrum-method fft)
expect(sample_stats_spectrum_method_needs_torus 2 "--spectrum-method needs --periodic" sample-stats --input ${WORK}/torus.txt --spectrum-method direct)

# Point-cloud readers: a truncated or malformed OFF, XYZ or PLY file is an error naming the line or the reason;
# XYZ blank lines (also CR-only and indented) and indented comments are skipped.
file(WRITE ${WORK}/trunc.off "OFF\n3 0 0\n0 0 0\n1 0 0\n")
expect(off_truncated 1 "trunc.off: unexpected end of file after 2 of 3 vertex lines" sample --input ${WORK}/trunc.off --count 1 --out ${WORK}/o.xyz --quiet)
file(WRITE ${WORK}/word.off "OFF\n2 0 0\n0 0 0\n1 abc 0\n")
expect(off_word 1 "word.off:4: 'abc' is not a number \\(vertex 1\\)" sample --input ${WORK}/word.off --count 1 --out ${WORK}/o.xyz --quiet)
file(WRITE ${WORK}/nan.off "OFF\n2 0 0\n0 0 0\nnan 0 0\n")
expect(off_nan 1 "nan.off:4: point 1 has a non-finite coordinate" sample --input ${WORK}/nan.off --count 1 --out ${WORK}/o.xyz --quiet)
file(WRITE ${WORK}/faces.off "OFF 3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n")
expect(off_with_faces 0 "\"points\": 3, \"kept\": 2" sample --input ${WORK}/faces.off --count 2 --out ${WORK}/o.xyz --quiet)
file(WRITE ${WORK}/mixed.xyz "0 0 0\n1 1 1 0 0 1\n")
expect(xyz_mixed_columns 1 "mixed.xyz:2: point 1 has 6 numbers, the first point has 3" sample --input ${WORK}/mixed.xyz --count 1 --out ${WORK}/o.xyz --quiet)
file(WRITE ${WORK}/suffix.xyz "0 0 0\n1 1 12abc\n")
expect(xyz_number_suffix 1 "suffix.xyz:2: '12abc' is not a number \\(point 1\\)" sample --input ${WORK}/suffix.xyz --count 1 --out ${WORK}/o.xyz --quiet)
file(WRITE ${WORK}/blank_first.xyz "   \n\r\n  # an indented comment\n0 0 0\r\n1 1 1\r\n2 0 1\n")
expect(xyz_blank_first_lines 0 "\"points\": 3, \"kept\": 2" sample --input ${WORK}/blank_first.xyz --count 2 --out ${WORK}/o.xyz --quiet)
file(WRITE ${WORK}/short.ply "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\nend_header\n0 0 0\n1 1\n")
expect(ply_short_line 1 "short.ply: not a readable PLY point cloud \\(vertex 1 has 2 values, the header declares 3 properties\\)" sample --input ${WORK}/short.ply --count 1 --out ${WORK}/o.xyz --quiet)
file(WRITE ${WORK}/cut.ply "ply\nformat binary_little_endian 1.0\nelement vertex 100\nproperty float x\nproperty float y\nproperty float z\nend_header\nabc")
expect(ply_truncated_binary 1 "cut.ply: not a readable PLY point cloud \\(truncated: 100 vertices of 12 bytes need 1200 bytes" sample --input ${WORK}/cut.ply --count 1 --out ${WORK}/o.xyz --quiet)
# List properties: their counts are checked against the data before CGAL reads (an 80-byte file claiming 4e9 items
# made it allocate 16 GB), in every element, also one before the vertices; lists that fit are read.
file(WRITE ${WORK}/blist.ply "ply\nformat binary_little_endian 1.0\nelement vertex 1\nproperty float x\nproperty float y\nproperty float z\nproperty list uchar float extra\nend_header\nabcdefghijklz")
expect(ply_binary_list_claims 1 "blist.ply: not a readable PLY point cloud \\(element vertex row 0: list extra claims 122 items, the file has 0 bytes left\\)" sample --input ${WORK}/blist.ply --count 1 --out ${WORK}/o.xyz --quiet)
file(WRITE ${WORK}/alist.ply "ply\nformat ascii 1.0\nelement face 1\nproperty list uchar int vertex_indices\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\nend_header\n200 0 1 2\n0 0 0\n1 0 0\n0 1 0\n")
expect(ply_ascii_list_claims 1 "alist.ply: not a readable PLY point cloud \\(face 0 has 4 values, too few for the 200 items of its list vertex_indices\\)" sample --input ${WORK}/alist.ply --count 1 --out ${WORK}/o.xyz --quiet)
file(WRITE ${WORK}/vlist.ply "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\nproperty list uchar float extra\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0 2 7 8\n1 0 0 0\n0 1 0 1 5\n3 0 1 2\n")
expect(ply_lists_that_fit 0 "\"points\": 3, \"kept\": 2" sample --input ${WORK}/vlist.ply --count 2 --out ${WORK}/o.xyz --quiet)
# PLY colours (red, green, blue as uchar) stay with their points in a PLY output: every kept row is an input row.
set(color_rows "0 0 0 10 20 30" "4 0 0 11 21 31" "0 4 0 12 22 32" "4 4 0 13 23 33" "2 2 0 14 24 34" "8 8 0 15 25 35")
string(REPLACE ";" "\n" color_body "${color_rows}")
file(WRITE ${WORK}/colors.ply "ply\nformat ascii 1.0\nelement vertex 6\nproperty float x\nproperty float y\nproperty float z\nproperty uchar red\nproperty uchar green\nproperty uchar blue\nend_header\n${color_body}\n")
expect(sample_colors 0 "\"kept\": 3,.*\"colors\": \"file\"" sample --input ${WORK}/colors.ply --count 3 --out ${WORK}/colors_out.ply --quiet)
file(STRINGS ${WORK}/colors_out.ply color_out)
list(FIND color_out "end_header" color_end)
list(SUBLIST color_out ${color_end} -1 color_kept)
list(REMOVE_AT color_kept 0)
list(LENGTH color_kept color_kept_count)
if(NOT color_kept_count EQUAL 3 OR NOT "${color_out}" MATCHES "property uchar red;property uchar green;property uchar blue")
  message(SEND_ERROR "sample_colors: expected 3 rows after a header with red, green, blue: ${color_out}")
endif()
foreach(row IN LISTS color_kept)
  list(FIND color_rows "${row}" color_found)
  if(color_found LESS 0)
    message(SEND_ERROR "sample_colors: output row '${row}' is no input row (a colour moved to another point?)")
  endif()
endforeach()
expect(sample_colors_estimated_normals 0 "\"normals\": \"estimated\", \"colors\": \"file\"" sample --input ${WORK}/colors.ply --count 3 --sigma-feature 0.5 --normal-neighbors 4 --out ${WORK}/colors_n.ply --quiet)
expect_count(${WORK}/colors_n.ply "property float nz|property double nz" 1)
expect(sample_colors_dropped 0 "\"colors\": \"dropped\"" sample --input ${WORK}/colors.ply --count 3 --out ${WORK}/colors_out.xyz --quiet)
# An empty cloud is degenerate, not an error: darts at a radius keep nothing (an empty file and a warning); a count
# is refused as any count above the points (both files were refused as holding no points).
file(WRITE ${WORK}/empty_cloud.xyz "")
expect(sample_empty_cloud 0 "\"points\": 0, \"kept\": 0,.*holds no points: the sample is empty" sample --input ${WORK}/empty_cloud.xyz --method darts --radius 0.1 --out ${WORK}/empty_out.ply --quiet)
expect_count(${WORK}/empty_out.ply "element vertex 0" 1)
expect(sample_empty_cloud_count 2 "--count 3 exceeds the 0 points" sample --input ${WORK}/empty_cloud.xyz --count 3 --out ${WORK}/empty_out.xyz)
# OFF colours are not read: reported as dropped (they read "none").
file(WRITE ${WORK}/colors.off "COFF\n4 0 0\n0 0 0 255 0 0 255\n1 0 0 0 255 0 255\n0 1 0 0 0 255 255\n1 1 0 9 9 9 255\n")
expect(sample_off_colors_dropped 0 "\"kept\": 2,.*\"colors\": \"dropped\"" sample --input ${WORK}/colors.off --count 2 --out ${WORK}/colors_off.ply --quiet)
expect(sample_no_colors 0 "\"colors\": \"none\"" sample --input ${WORK}/wall.xyz --count 50 --out ${WORK}/s.ply --quiet)
file(WRITE ${WORK}/colors_bin.ply "ply\nformat binary_little_endian 1.0\nelement vertex 2\nproperty float x\nproperty float y\nproperty float z\nproperty uchar red\nproperty uchar green\nproperty uchar blue\nend_header\nabcdefghijklABCmnopqrstuvwxDEF")
expect(sample_colors_binary 0 "\"kept\": 2,.*\"colors\": \"file\"" sample --input ${WORK}/colors_bin.ply --count 2 --out ${WORK}/colors_bin_out.ply --quiet)
expect_count(${WORK}/colors_bin_out.ply " 65 66 67\n" 1)
expect_count(${WORK}/colors_bin_out.ply " 68 69 70\n" 1)
# An ASCII integer out of its type's range is refused (CGAL cast it: a green of 300 became 44, -1 became 255).
file(WRITE ${WORK}/colors_range.ply "ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\nproperty float y\nproperty float z\nproperty uchar red\nproperty uchar green\nproperty uchar blue\nend_header\n0 0 0 1 2 3\n1 0 0 0 300 0\n")
expect(sample_colors_range 1 "colors_range.ply: not a readable PLY point cloud \\(vertex 1: green is 300, not a uchar \\(an integer in \\[0, 255\\]\\)\\)" sample --input ${WORK}/colors_range.ply --count 1 --out ${WORK}/a.ply)
file(WRITE ${WORK}/colors_frac.ply "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nproperty float z\nproperty uchar red\nproperty uchar green\nproperty uchar blue\nend_header\n0 0 0 1 2.5 3\n")
expect(sample_colors_fraction 1 "vertex 0: green is 2.5, not a uchar" sample --input ${WORK}/colors_frac.ply --count 1 --out ${WORK}/a.ply)
file(WRITE ${WORK}/red_only.ply "ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\nproperty float y\nproperty float z\nproperty uchar red\nend_header\n0 0 0 1\n1 1 1 2\n")
expect(ply_some_colors 1 "red_only.ply: .*only some of the colour properties red, green, blue" sample --input ${WORK}/red_only.ply --count 1 --out ${WORK}/o.ply --quiet)
file(WRITE ${WORK}/short_colors.ply "ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\nproperty float y\nproperty float z\nproperty ushort red\nproperty ushort green\nproperty ushort blue\nend_header\n0 0 0 1 2 3\n1 1 1 2 3 4\n")
expect(ply_wide_colors 1 "short_colors.ply: .*vertex property red is ushort: colours must be uchar" sample --input ${WORK}/short_colors.ply --count 1 --out ${WORK}/o.ply --quiet)
# PLY vertices CGAL would misread are refused naming the problem: integer coordinates (CGAL's reader crashed), a
# line with a value too many (read shifted onto the next points), no x property (read as the origin), some of the
# normals, a NaN.
set(ply_head "ply\nformat ascii 1.0\nelement vertex 3\n")
file(WRITE ${WORK}/int.ply "${ply_head}property int x\nproperty int y\nproperty int z\nend_header\n1 2 3\n3 4 5\n5 6 8\n")
expect(ply_int 1 "int.ply: not a readable PLY point cloud \\(vertex property x is int: coordinates and normals must be float or double\\)" sample --input ${WORK}/int.ply --count 2 --out ${WORK}/o.xyz --quiet)
file(WRITE ${WORK}/extra.ply "${ply_head}property float x\nproperty float y\nproperty float z\nend_header\n1 2 3 4\n3 4 5\n5 6 8\n")
expect(ply_extra_value 1 "extra.ply: not a readable PLY point cloud \\(vertex 0 has 4 values, the header declares 3 properties\\)" sample --input ${WORK}/extra.ply --count 2 --out ${WORK}/o.xyz --quiet)
file(WRITE ${WORK}/abc.ply "${ply_head}property float a\nproperty float b\nproperty float c\nend_header\n1 2 3\n3 4 5\n5 6 8\n")
expect(ply_no_x 1 "abc.ply: not a readable PLY point cloud \\(the vertex element has no property x\\)" sample-stats --input ${WORK}/abc.ply)
file(WRITE ${WORK}/nx.ply "${ply_head}property float x\nproperty float y\nproperty float z\nproperty float nx\nend_header\n1 2 3 1\n3 4 5 1\n5 6 8 1\n")
expect(ply_some_normals 1 "nx.ply: .*only some of the normal properties" sample --input ${WORK}/nx.ply --count 2 --out ${WORK}/o.xyz --quiet)
file(WRITE ${WORK}/nan.ply "${ply_head}property float x\nproperty float y\nproperty float z\nend_header\n1 2 3\nnan 1 1\n0 0 0\n")
expect(ply_nan 1 "nan.ply: not a readable PLY point cloud \\(vertex 1: 'nan' is not a finite number\\)" sample-stats --input ${WORK}/nan.ply)
expect(sigma_feature_inf 0 "\"kept\": 2,.*\"sigma_feature\": null," sample --input ${WORK}/blank_first.xyz --count 2 --sigma-feature inf --out ${WORK}/o.xyz --quiet)
expect(sigma_feature_minus_inf 2 "--sigma-feature must be a finite number, got '-inf'" sample --input ${WORK}/blank_first.xyz --count 2 --sigma-feature -inf --out ${WORK}/o.xyz)
expect(unoriented_without_sigma 2 "--unoriented goes with --sigma-feature" sample --input ${WORK}/blank_first.xyz --count 2 --unoriented --out ${WORK}/o.xyz)
expect(normal_neighbors_without_sigma 2 "--normal-neighbors goes with --sigma-feature" sample --input ${WORK}/blank_first.xyz --count 2 --normal-neighbors 8 --out ${WORK}/o.xyz)
expect(normal_neighbors_huge 2 "--normal-neighbors must be in \\[3, 1000000\\]" sample --input ${WORK}/blank_first.xyz --count 2 --sigma-feature 0.5 --normal-neighbors 4294967296 --out ${WORK}/o.xyz)
# Numbers are decimal (strtod also read 0x10 as 16); a missing input says so before its extension is judged.
expect(hex_option 2 "--radius must be a finite number, got '0x10'" rips --points ${DATA}/figure_eight.xyz --radius 0x10 --out ${WORK}/x.txt)
file(WRITE ${WORK}/hex.xyz "0 0 0\n0x10 1 1\n")
expect(hex_coordinate 1 "hex.xyz:2: '0x10' is not a number" sample --input ${WORK}/hex.xyz --count 1 --out ${WORK}/o.xyz --quiet)
expect(missing_extensionless_input 1 "nowhere/none: cannot open for reading" sample --input ${WORK}/nowhere/none --count 1 --out ${WORK}/o.xyz --quiet)
# sample-stats: --sigma-feature without normals is refused (was ignored), a zero normal named (was null statistics).
expect(sample_stats_sigma_without_normals 2 "--sigma-feature needs normals in .*blank_first.xyz" sample-stats --input ${WORK}/blank_first.xyz --sigma-feature 0.5)
file(WRITE ${WORK}/zero_normal.xyz "0 0 0 0 0 1\n1 0 0 0 0 0\n0 1 0 0 0 1\n")
expect(sample_zero_normal 1 "zero_normal.xyz:2: point 1 has a zero normal" sample --input ${WORK}/zero_normal.xyz --count 2 --sigma-feature 0.5 --out ${WORK}/o.xyz --quiet)
expect(sample_stats_zero_normal 1 "zero_normal.xyz:2: point 1 has a zero normal" sample-stats --input ${WORK}/zero_normal.xyz --sigma-feature 0.5)
# Euclidean runs never compare normals: a zero normal is carried along, not refused.
expect(sample_zero_normal_euclidean 0 "\"kept\": 2," sample --input ${WORK}/zero_normal.xyz --count 2 --out ${WORK}/zero_normal_out.xyz --quiet)
expect(sample_stats_zero_normal_euclidean 0 "\"samples\": [0-9]+," sample-stats --input ${WORK}/zero_normal.xyz)
# Outputs of the wrong kind are refused before the work, naming the option (exit 2).
expect(sample_out_extension 2 "--out writes a point cloud \\(or, for points in the plane, text\\): give a file ending in .ply, .off, .xyz or .txt, got '.*o.csv'" sample --input ${WORK}/wall.xyz --count 5 --out ${WORK}/o.csv)
expect(sample_image_picture_extension 2 "--picture writes a raster picture: give a file ending in .png, .jpg, .jpeg, .pgm or .ppm" sample-image --input ${WORK}/line.pgm --count 5 --picture ${WORK}/p.txt)
# sample-stats: the spectrum of 3-D samples is refused; an empty file is degenerate, not an error; the domain
# measure printed is the one used.
expect(sample_stats_spectrum_3d 2 "--spectrum, --max-frequency and --spectrum-method need 2-D samples on a torus; .*wall_plain.xyz has 3 numbers per line" sample-stats --input ${WORK}/wall_plain.xyz --periodic --spectrum ${WORK}/s3.csv)
file(WRITE ${WORK}/nothing.txt "# no samples\n")
expect(sample_stats_empty 0 "\"samples\": 0,.*\"relative_radius\": null, \"average_minimum_distance\": null, \"degenerate\": true" sample-stats --input ${WORK}/nothing.txt)
# Spacing statistics of two kept points are undefined: null (they read 0, as if maximally clumped).
file(WRITE ${WORK}/five.xyz "0 0 0\n1 0 0\n0 1 0\n1 1 0\n0.5 0.5 0\n")
expect(sample_two_kept 0 "\"kept\": 2,.*\"relative_radius\": null, \"bilateral_relative_radius\": null, \"average_minimum_distance\": null" sample --input ${WORK}/five.xyz --count 2 --out ${WORK}/o.xyz --quiet)
expect(sample_stats_domain 0 "\"domain_measure\": 1, \"periodic\": true" sample-stats --input ${WORK}/torus.txt --periodic)
# synthetic-city: sizes that would fill the memory are refused naming the options.
expect(synthetic_city_tiny_interval 2 "more than 2\\^26 fixes .*raise speed .* or sampling_interval .*\\(on the command line: sampling_interval is --interval" synthetic-city --interval 1e-9 --out-tracks ${WORK}/a --out-vertices ${WORK}/b --out-edges ${WORK}/c)
# Blocks so large that one route needs billions of fixes: the message names the block size too.
expect(synthetic_city_huge_blocks 2 "more than 2\\^26 fixes .*along a route of .*block_width \\(1e\\+300\\)" synthetic-city --block-width 1e300 --trips 1 --out-tracks ${WORK}/a --out-vertices ${WORK}/b --out-edges ${WORK}/c)
expect(synthetic_city_huge_blocks 2 "beyond the largest double: block_width" synthetic-city --block-width 1e307 --columns 100 --out-tracks ${WORK}/a --out-vertices ${WORK}/b --out-edges ${WORK}/c)
# --graph edge lengths whose squares overflow are computed scaled; beyond the largest double they are refused.
file(WRITE ${WORK}/far_graph.txt "3 2\n0 0 0 0\n1e200 0 0 1\n2e200 0 0 2\n0 1\n1 2\n")
expect(graph_huge_coordinates 0 "\"nodes\": 2, \"arcs\": 1" skeleton --graph ${WORK}/far_graph.txt --out-vertices ${WORK}/a --out-edges ${WORK}/b --quiet)
file(WRITE ${WORK}/too_far_graph.txt "2 1\n-1.5e308 0 0 0\n1.5e308 0 0 1\n0 1\n")
expect(graph_length_overflow 1 "too_far_graph.txt: the edge between points 0 and 1 is longer than the largest double" skeleton --graph ${WORK}/too_far_graph.txt --out-vertices ${WORK}/a --out-edges ${WORK}/b --quiet)
expect(synthetic_city_huge_organic 2 "beyond the largest double: block_width or block_height too large" synthetic-city --layout organic --block-width 1e308 --block-height 1 --lane-offset 0 --trips 1 --out-tracks ${WORK}/a --out-vertices ${WORK}/b --out-edges ${WORK}/c)
expect(sample_stats_empty_measure 0 "\"samples\": 0,.*\"domain_measure\": 5," sample-stats --input ${WORK}/nothing.txt --domain-measure 5)
expect(sample_stats_empty_spectrum 1 "nothing.txt: no samples to take the spectrum of" sample-stats --input ${WORK}/nothing.txt --periodic --spectrum ${WORK}/s0.csv)
# sample-stats on a flat 10 x 10 grid in space (spacing 1): an XYZ file is a cloud as `sample` reads it, the same
# as its PLY (it was read as points in a volume: measure 0, degenerate); --intrinsic-dimension 2 measures the
# estimated surface, not the bounding box's volume; the statistics of a degenerate set are null, not 0; an empty
# PLY is degenerate like an empty text file (it was an error).
set(grid_xyz "")
set(grid_ply "ply\nformat ascii 1.0\nelement vertex 100\nproperty double x\nproperty double y\nproperty double z\nend_header\n")
foreach(i RANGE 9)
  foreach(j RANGE 9)
    string(APPEND grid_xyz "${i} ${j} 0\n")
    string(APPEND grid_ply "${i} ${j} 0\n")
  endforeach()
endforeach()
file(WRITE ${WORK}/grid3.xyz "${grid_xyz}")
file(WRITE ${WORK}/grid3.ply "${grid_ply}")
expect(sample_stats_xyz_cloud 0 "\"intrinsic_dimension\": 2, \"domain_measure\": 1[0-9][0-9](\\.[0-9]+)?, .*\"degenerate\": false" sample-stats --input ${WORK}/grid3.xyz)
string(REGEX REPLACE "\"input\": \"[^\"]*\", \"samples\"" "" xyz_stats "${last_output}")
string(REGEX REPLACE "\"seconds\": [^,}]*" "" xyz_stats "${xyz_stats}")
expect(sample_stats_ply_cloud 0 "\"degenerate\": false" sample-stats --input ${WORK}/grid3.ply)
string(REGEX REPLACE "\"input\": \"[^\"]*\", \"samples\"" "" ply_stats "${last_output}")
string(REGEX REPLACE "\"seconds\": [^,}]*" "" ply_stats "${ply_stats}")
if(NOT xyz_stats STREQUAL ply_stats)
  message(SEND_ERROR "sample-stats: grid3.xyz and grid3.ply differ:\n${xyz_stats}\n${ply_stats}")
endif()
expect(sample_stats_surface 0 "\"intrinsic_dimension\": 2, \"domain_measure\": 1[0-9][0-9](\\.[0-9]+)?, .*\"degenerate\": false" sample-stats --input ${WORK}/grid3.ply --intrinsic-dimension 2)
file(WRITE ${WORK}/grid3_points.txt "${grid_xyz}")
expect(sample_stats_surface_text 0 "\"intrinsic_dimension\": 2, \"domain_measure\": 1[0-9][0-9](\\.[0-9]+)?, .*\"degenerate\": false" sample-stats --input ${WORK}/grid3_points.txt --intrinsic-dimension 2)
# A given area does not make a surface cloud a volume: its dimension is still estimated (it was 3: degenerate here,
# rho 3 times too low on a fandisk sample); rho = 1 / sqrt(2 * 81 / (sqrt(3) * 100)) = 1.034.
expect(sample_stats_surface_measure 0 "\"intrinsic_dimension\": 2, \"domain_measure\": 81, .*\"relative_radius\": 1\\.03[0-9]*, .*\"degenerate\": false" sample-stats --input ${WORK}/grid3.xyz --domain-measure 81)
expect(sample_stats_volume_text 0 "\"intrinsic_dimension\": 3, \"domain_measure\": 0, .*\"degenerate\": true" sample-stats --input ${WORK}/grid3_points.txt)
file(WRITE ${WORK}/two_points.txt "0 0\n3 4\n")
expect(sample_stats_degenerate_null 0 "\"hexagonal_distance\": null, \"minimum_distance\": null, \"relative_radius\": null, \"average_minimum_distance\": null, \"degenerate\": true" sample-stats --input ${WORK}/two_points.txt)
file(WRITE ${WORK}/empty.ply "ply\nformat ascii 1.0\nelement vertex 0\nproperty double x\nproperty double y\nproperty double z\nend_header\n")
expect(sample_stats_empty_ply 0 "\"samples\": 0,.*\"degenerate\": true" sample-stats --input ${WORK}/empty.ply)
expect(sample_stats_max_frequency_cap 2 "--max-frequency must be at most 16384 .*got 16385" sample-stats --input ${WORK}/torus.txt --periodic --max-frequency 16385)
expect(synthetic_city_trips_cap 2 "--trips must be at most 67108864, got 67108865" synthetic-city --trips 67108865 --out-tracks ${WORK}/a --out-vertices ${WORK}/b --out-edges ${WORK}/c)
# Audit of the command line (mutation testing of src/cli): each audit_ test pins a property the help or the
# README promises that no earlier test checked.
# sample: elimination needs --count, which must be >= 1 and may equal the number of points (all kept);
# --normal-neighbors in [3, 1000000] (default 18); --seed >= 0.
expect(audit_sample_elimination_radius 2 "--method elimination needs --count M" sample --input ${WORK}/candidates.txt --radius 0.1 --out ${A}/s.txt)
expect(audit_sample_count_zero 2 "--count must be >= 1, got 0" sample --input ${WORK}/candidates.txt --count 0 --out ${A}/s.txt)
expect(audit_sample_all_points 0 "\"points\": 1500, \"kept\": 1500," sample --input ${WORK}/candidates.txt --count 1500 --out ${A}/s.txt --quiet)
expect(audit_sample_neighbors_two 2 "--normal-neighbors must be in \\[3, 1000000\\]" sample --input ${WORK}/wall_plain.xyz --count 10 --sigma-feature 0.5 --normal-neighbors 2 --out ${A}/s.xyz)
expect(audit_sample_seed_negative 2 "--seed must be >= 0" sample --input ${WORK}/wall.xyz --count 10 --seed -1 --out ${A}/s.xyz)
expect(audit_sample_neighbors_default 0 "\"normals\": \"estimated\"" sample --input ${WORK}/wall_plain.xyz --count 50 --sigma-feature 0.5 --out ${A}/n_default.xyz --quiet)
expect(audit_sample_neighbors_18 0 "\"normals\": \"estimated\"" sample --input ${WORK}/wall_plain.xyz --count 50 --sigma-feature 0.5 --normal-neighbors 18 --out ${A}/n_18.xyz --quiet)
expect_same_file(${A}/n_default.xyz ${A}/n_18.xyz "audit_sample_neighbors_default: the default is not 18 neighbours")
# --unoriented: a normal and its opposite are one direction, so the wall (opposite normals on its two sheets)
# samples as the same wall with all normals up.
file(STRINGS ${WORK}/wall.xyz audit_wall)
list(TRANSFORM audit_wall REPLACE " 0 0 -1$" " 0 0 1")
list(TRANSFORM audit_wall APPEND "\n")
string(JOIN "" audit_wall_up ${audit_wall})
file(WRITE ${A}/wall_up.xyz "${audit_wall_up}")
expect(audit_sample_unoriented 0 "\"orientation\": \"unoriented\"" sample --input ${WORK}/wall.xyz --count 100 --sigma-feature 0.5 --unoriented --out ${A}/wall_u.xyz --quiet)
expect(audit_sample_up 0 "\"orientation\": \"oriented\"" sample --input ${A}/wall_up.xyz --count 100 --sigma-feature 0.5 --out ${A}/wall_up_s.xyz --quiet)
file(STRINGS ${A}/wall_u.xyz audit_u)
file(STRINGS ${A}/wall_up_s.xyz audit_up)
list(TRANSFORM audit_u REPLACE " [^ ]+ [^ ]+ [^ ]+$" "")
list(TRANSFORM audit_up REPLACE " [^ ]+ [^ ]+ [^ ]+$" "")
if(NOT audit_u STREQUAL audit_up)
  message(SEND_ERROR "audit_sample_unoriented: --unoriented kept other points than the wall with all normals up")
endif()
# sample-stats: --intrinsic-dimension is 2 or 3; --sigma-feature needs normals also for text points in the plane;
# --spectrum-method gridded is named as such; an empty set on the torus measures 1; --quiet silences the note;
# the spectrum file has the columns its header names (radial power at frequency 0 is the count, 256).
expect(audit_stats_dimension_one 2 "--intrinsic-dimension must be 2 or 3" sample-stats --input ${DATA}/figure_eight.xyz --intrinsic-dimension 1)
expect(audit_stats_sigma_plane 2 "--sigma-feature needs normals in .*torus.txt \\(lines 'x y z nx ny nz', or PLY / OFF\\)" sample-stats --input ${WORK}/torus.txt --sigma-feature 0.5)
expect(audit_stats_gridded 0 "\"spectrum_method\": \"gridded\"" sample-stats --input ${WORK}/torus.txt --periodic --spectrum-method gridded --quiet)
expect(audit_stats_empty_torus 0 "\"samples\": 0,.*\"domain_measure\": 1, \"periodic\": true" sample-stats --input ${WORK}/nothing.txt --periodic --quiet)
expect(audit_stats_quiet_note 0 "\"samples\": 200," sample-stats --input ${WORK}/euclid.xyz --quiet)
if(NOT last_error STREQUAL "")
  message(SEND_ERROR "audit_stats_quiet_note: --quiet still wrote to standard error:\n${last_error}")
endif()
expect(audit_stats_spectrum_columns 0 "\"effective_nyquist\": " sample-stats --input ${WORK}/torus.txt --periodic --spectrum ${A}/spectrum.csv --quiet)
expect_count(${A}/spectrum.csv "^frequency,radial_power,anisotropy_db\n0,255\\.99[0-9]*,0\n0\\.125,20\\.35[0-9]*,-1\\.94" 1)
# sample --periodic with darts at a radius: distances of the unit torus, so no two kept points are closer than R
# there (sample-stats --periodic measures them).
expect(audit_sample_darts_periodic 0 "\"method\": \"darts\", \"radius\": 0.05,.*\"periodic\": true" sample --input ${WORK}/candidates.txt --method darts --radius 0.05 --periodic --out ${A}/dp.txt --quiet)
expect(audit_sample_darts_periodic_stats 0 "\"minimum_distance\": 0\\.(0[5-9]|[1-9])[0-9]*, " sample-stats --input ${A}/dp.txt --periodic --quiet)
# sample's bilateral_relative_radius is rho in the sampler's metric: what sample-stats --sigma-feature measures on
# the kept points over the same domain.
expect(audit_sample_bilateral_rho 0 "\"kept\": 100, .*\"intrinsic_dimension\": 3, \"domain_measure\": ([0-9.]+), .*\"bilateral_relative_radius\": ([0-9.]+), " sample --input ${WORK}/wall.xyz --count 100 --sigma-feature 0.5 --out ${A}/b.xyz --quiet)
string(REGEX MATCH "\"domain_measure\": ([0-9.]+), .*\"bilateral_relative_radius\": ([0-9.]+), " _ "${last_output}")
set(audit_rho ${CMAKE_MATCH_2})
expect(audit_sample_bilateral_rho_stats 0 "\"relative_radius\": ${audit_rho}, " sample-stats --input ${A}/b.xyz --sigma-feature 0.5 --intrinsic-dimension 3 --domain-measure ${CMAKE_MATCH_1} --quiet)

# --period: the torus [0, 2) x [0, 1) instead of the unit one (implies --periodic). Darts at 0.05 over 1500
# candidates of that rectangle keep no pair closer than 0.05 on its torus (sample-stats --period measures it),
# the measure is 2; the plain throw of the same candidates keeps pairs closer across the seam x = 0 / 2.
random_points(${WORK}/wide.txt 54321 2)
expect(sample_period_darts 0 "\"method\": \"darts\", \"radius\": 0.05,.*\"periodic\": true, \"period\": \\[2, 1\\], \"intrinsic_dimension\": 2, \"domain_measure\": 2," sample --input ${WORK}/wide.txt --method darts --radius 0.05 --period 2,1 --out ${WORK}/wide_tile.txt --quiet)
expect(sample_period_darts_stats 0 "\"domain_measure\": 2, \"periodic\": true, \"period\": \\[2, 1\\], .*\"minimum_distance\": 0\\.(0[5-9]|[1-9])[0-9]*, " sample-stats --input ${WORK}/wide_tile.txt --period 2,1 --quiet)
expect(sample_period_plain 0 "\"periodic\": false, \"period\": null," sample --input ${WORK}/wide.txt --method darts --radius 0.05 --out ${WORK}/wide_plain.txt --quiet)
expect(sample_period_plain_stats 0 "\"minimum_distance\": 0\\.0[0-4][0-9]*, " sample-stats --input ${WORK}/wide_plain.txt --period 2,1 --quiet)
# One length stands for every axis; the spectrum is measured as on the torus scaled to area 1 (period 1 gives
# what --periodic gives); refusals name the option.
expect(sample_stats_period_one_length 0 "\"period\": \\[2, 2\\]," sample-stats --input ${WORK}/wide_tile.txt --period 2 --quiet)
expect(sample_stats_period_unit 0 "\"period\": \\[1, 1\\], .*\"effective_nyquist\": " sample-stats --input ${WORK}/tile.txt --period 1 --quiet)
string(REGEX MATCH "\"effective_nyquist\": [^,]*, \"oscillation\": [^,]*," period_unit_spectrum "${last_output}")
expect(sample_stats_periodic_unit 0 "\"period\": null, .*\"effective_nyquist\": " sample-stats --input ${WORK}/tile.txt --periodic --quiet)
string(REGEX MATCH "\"effective_nyquist\": [^,]*, \"oscillation\": [^,]*," periodic_unit_spectrum "${last_output}")
if(NOT period_unit_spectrum STREQUAL periodic_unit_spectrum OR period_unit_spectrum STREQUAL "")
  message(SEND_ERROR "sample_stats_period_unit: '${period_unit_spectrum}' differs from '${periodic_unit_spectrum}'")
endif()
# Unequal lengths: 300 points eliminated on the torus 2 x 1 have a zero region in its spectrum (nu_eff 0.44,
# annuli 0..104 for F = 6 sqrt(300), each 2 / sqrt(300) units wide); eliminated in the plane, the seams leave
# none.
expect(sample_period_elimination 0 "\"kept\": 300," sample --input ${WORK}/wide.txt --count 300 --period 2,1 --out ${WORK}/wide_300.txt --quiet)
expect(sample_stats_period_spectrum_box 0 "\"period\": \\[2, 1\\], .*\"effective_nyquist\": 0\\.[3-5]" sample-stats --input ${WORK}/wide_300.txt --period 2,1 --spectrum ${WORK}/box.csv --quiet)
expect_count(${WORK}/box.csv "\n" 106)
file(STRINGS ${WORK}/box.csv box_lines LIMIT_COUNT 3)
list(GET box_lines 2 box_first_annulus)
if(NOT box_first_annulus MATCHES "^0\\.11547005")
  message(SEND_ERROR "sample_stats_period_spectrum_box: annulus 1 at '${box_first_annulus}', not 2 / sqrt(300)")
endif()
expect(sample_period_elimination_plain 0 "\"kept\": 300," sample --input ${WORK}/wide.txt --count 300 --out ${WORK}/wide_300_plain.txt --quiet)
expect(sample_stats_period_spectrum_plain 0 "\"effective_nyquist\": 0," sample-stats --input ${WORK}/wide_300_plain.txt --period 2,1 --quiet)
# Above an aspect ratio of 4 the spectrum's sums cost more than 4 squares: printed only when asked.
expect(sample_stats_period_strip 0 "\"period\": \\[16, 1\\], [^}]*\"degenerate\": false}" sample-stats --input ${WORK}/wide_300.txt --period 16,1 --quiet)
expect(sample_stats_period_strip_asked 0 "\"degenerate\": false, \"effective_nyquist\": " sample-stats --input ${WORK}/wide_300.txt --period 16,1 --max-frequency 20 --quiet)
expect(sample_period_three_for_two 2 "--period has 3 lengths for 2-D points \\(give one, or one per axis\\)" sample --input ${WORK}/wide.txt --count 5 --period 2,1,1 --out ${WORK}/x.txt)
expect(sample_period_zero 2 "--period takes one length or one per axis, each a number in \\[1e-150, 1e150\\] separated by commas, got '2,0'" sample --input ${WORK}/wide.txt --count 5 --period 2,0 --out ${WORK}/x.txt)
expect(sample_period_word 2 "got 'a,b'" sample-stats --input ${WORK}/wide.txt --period a,b)
expect(sample_period_empty_part 2 "got '2,'" sample-stats --input ${WORK}/wide.txt --period 2,)
# A cloud in space: one length for the three axes, the torus's volume as the measure.
expect(sample_cloud_period 0 "\"kept\": 50,.*\"periodic\": true, \"period\": \\[40, 40, 40\\], \"intrinsic_dimension\": 3, \"domain_measure\": 64000," sample --input ${WORK}/wall_plain.xyz --count 50 --period 40 --out ${WORK}/wall_period.xyz --quiet)
# No samples: degenerate, not an error; the lengths are taken as given (the dimension is unknown).
expect(sample_stats_period_empty 0 "\"samples\": 0, .*\"domain_measure\": 2, \"periodic\": true, \"period\": \\[2, 1\\], .*\"degenerate\": true" sample-stats --input ${WORK}/nothing.txt --period 2,1)
