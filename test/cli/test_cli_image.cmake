# SPDX-License-Identifier: GPL-3.0-or-later
# Pictures: sample-image, stipple and bilateral-filter, the picture readers and writers.
# Run by ctest as cli_image with the variables of cli_common.cmake.
include(${CMAKE_CURRENT_LIST_DIR}/cli_common.cmake)

# sample-image: a 48 x 48 grey PGM (ASCII) with a dark column one pixel wide, and a 4 x 3 colour PPM.
set(pgm "P2\n48 48\n255\n")
foreach(row RANGE 47)
  foreach(column RANGE 47)
    if(column EQUAL 24)
      string(APPEND pgm "10 ")
    else()
      string(APPEND pgm "220 ")
    endif()
  endforeach()
  string(APPEND pgm "\n")
endforeach()
file(WRITE ${WORK}/line.pgm "${pgm}")
file(WRITE ${WORK}/tiny.ppm "P3\n4 3\n255\n255 0 0 0 255 0 0 0 255 9 9 9\n1 2 3 4 5 6 7 8 9 10 11 12\n0 0 0 50 50 50 100 100 100 200 200 200\n")
# A --radius so large that every pixel neighbours every other is refused as the argument, exit 2 (it was the
# library's message about Elimination_options::max_neighbor_entries, exit 1): 160 x 160 pixels ask for 6.6e8
# neighbour entries, above the automatic limit of 2^29.
string(REPEAT "128 " 25600 grey_pixels)
file(WRITE ${WORK}/grey160.pgm "P2\n160 160\n255\n${grey_pixels}\n")
expect(sample_image_radius_too_large 2 "--radius 1000000 is too large for these items: give a smaller one, or none for the automatic radius" sample-image --input ${WORK}/grey160.pgm --count 10 --radius 1e6 --out ${WORK}/x.txt --quiet)
expect(sample_image_help 0 "usage: featurerecon sample-image --input IMAGE" sample-image --help)
expect(sample_image 0 "\"width\": 48, \"height\": 48, \"channels\": 1, \"method\": \"elimination\", \"samples\": 120,.*\"relative_radius\": "
       sample-image --input ${WORK}/line.pgm --count 120 --out ${WORK}/img.txt --svg ${WORK}/img.svg --quiet)
expect_count(${WORK}/img.txt "\n" 120)
expect_count(${WORK}/img.svg "<circle" 120)
# One sample has no spacing: null, as the help says (it printed 0).
expect(sample_image_one 0 "\"samples\": 1,.*\"relative_radius\": null, \"average_minimum_distance\": null" sample-image --input ${WORK}/line.pgm --method darts --radius 1e9 --out ${WORK}/img1.txt --quiet)
# Bilateral elimination fills the dark column (x = 24.5): 10 of the 120 samples land there (at least 8
# asked), Euclidean elimination puts 5 there.
expect(sample_image_bilateral 0 "\"samples\": 120" sample-image --input ${WORK}/line.pgm --count 120 --sigma-feature 0.1
       --out ${WORK}/img_b.txt --quiet)
file(STRINGS ${WORK}/img_b.txt on_line REGEX "^24.5 ")
list(LENGTH on_line on_line_count)
if(on_line_count LESS 8)
  message(SEND_ERROR "sample_image_bilateral: ${on_line_count} samples on the dark column, expected >= 8")
endif()
expect(sample_image_again 0 "\"samples\": 120" sample-image --input ${WORK}/line.pgm --count 120 --sigma-feature 0.1
       --out ${WORK}/img_b2.txt --quiet)
expect_same_file(${WORK}/img_b.txt ${WORK}/img_b2.txt "sample-image: the same seed gave different output")
expect(sample_image_darts 0 "\"method\": \"darts\", \"samples\": 60," sample-image --input ${WORK}/line.pgm --method darts --count 60
       --out ${WORK}/d.csv --quiet)
expect_count(${WORK}/d.csv "x,y,value\n" 1)
expect(sample_image_darts_radius 0 "\"method\": \"darts\".*\"radius\": 5," sample-image --input ${WORK}/line.pgm --method darts --radius 5
       --picture ${WORK}/d.png --quiet)
expect(sample_image_continuous 0 "\"method\": \"continuous\", \"samples\": 30,.*\"mosaic_psnr_db\": " sample-image --input ${WORK}/line.pgm
       --method continuous --radius 2 --count 30 --sigma-feature 0.1 --mosaic ${WORK}/m.ppm --quiet)
expect_count(${WORK}/m.ppm "^P6\n48 48\n255\n" 1)
# A radius that lets billions of samples into the picture needs --count (Groemer's bound: 2.66e9 at 0.001 on
# 48 x 48); with a count it runs. Colours let samples come closer than R, but bilinear colours change by at
# most sqrt(2) per pixel: R / sqrt(1 + 2 / S^2) apart at least (R 2, S 1: 1.15 px, runs; S 1e-4: refused).
expect(sample_image_continuous_unbounded 2 "--radius 0.001 lets up to 2.66e\\+09 samples into the 48 x 48 picture \\(more than 2\\^27"
       sample-image --input ${WORK}/line.pgm --method continuous --radius 0.001 --out ${WORK}/cu.txt --quiet)
expect(sample_image_continuous_colour_bounded 0 "\"method\": \"continuous\", \"samples\": " sample-image
       --input ${WORK}/line.pgm --method continuous --radius 2 --sigma-feature 1 --out ${WORK}/cu.txt --quiet)
expect(sample_image_continuous_colour_unbounded 2 "--radius 2 lets up to 1.33e\\+11 samples into the 48 x 48"
       sample-image --input ${WORK}/line.pgm --method continuous --radius 2 --sigma-feature 1e-4 --out ${WORK}/cu.txt)
expect(sample_image_continuous_capped 0 "\"samples\": 50," sample-image --input ${WORK}/line.pgm --method continuous --radius 0.001
       --count 50 --out ${WORK}/cu.txt --quiet)
expect(sample_image_rgb 0 "\"channels\": 3,.*\"samples\": 5" sample-image --input ${WORK}/tiny.ppm --count 5 --out ${WORK}/rgb.txt --quiet)
file(STRINGS ${WORK}/rgb.txt rgb_lines)
list(GET rgb_lines 0 rgb_first)
string(REGEX MATCHALL "[^ ]+" rgb_fields "${rgb_first}")
list(LENGTH rgb_fields rgb_field_count)
if(NOT rgb_field_count EQUAL 5)
  message(SEND_ERROR "sample_image_rgb: '${rgb_first}' should be 'x y r g b'")
endif()
expect(sample_image_grey 0 "\"channels\": 1," sample-image --input ${WORK}/tiny.ppm --grey --count 5 --out ${WORK}/g.txt --quiet)
expect(sample_image_bad_method 2 "--method must be elimination, darts or continuous" sample-image --input ${WORK}/line.pgm --method lloyd --count 5 --out ${WORK}/x.txt)
# stipple: every method gives the asked number of dots, the same seed the same picture; bad arguments explained.
# darts with --radius and --count: a cap, the first M kept in the seeded order, spread over the whole picture (the
# first M in pixel order used to fill only the top rows).
expect(sample_image_darts_cap 0 "\"method\": \"darts\", \"samples\": 50," sample-image --input ${WORK}/line.pgm --method darts
       --radius 3 --count 50 --out ${WORK}/cap.csv --quiet)
expect_count_at_least(${WORK}/cap.csv "\n[0-9.]+,(2[4-9]|[34][0-9])[.0-9]*," 10
                      "sample-image darts cap: samples in the lower half (of 50, about 25 expected)")
expect(stipple_help 0 "usage: featurerecon stipple IMAGE --count N" stipple --help)
# Iteration counts are bounded (10^12 ran for weeks).
expect(stipple_iterations_huge 2 "--iterations must be in \\[0, 1000000\\], got 1000000000000" stipple ${WORK}/line.pgm --count 40 --method lloyd --iterations 1000000000000 --out ${WORK}/st.svg)
expect(skeleton_smoothing_huge 2 "--smoothing must be an integer in \\[0, 1000000\\], got 1000000000000" skeleton --points ${DATA}/figure_eight.xyz --radius 0.6 --smoothing 1000000000000 --out-vertices ${WORK}/a --out-edges ${WORK}/b)
expect(skeleton_smoothing_method_bad 2 "--smoothing-method must be taubin or laplacian, got 'cubic'" skeleton --points ${DATA}/figure_eight.xyz --radius 0.6 --smoothing-method cubic --out-vertices ${WORK}/a --out-edges ${WORK}/b)
# One dot: the radius search must stop once a throw keeps a single dot (it used to grow the radius to infinity).
foreach(method darts kernel)
  expect(stipple_one_${method} 0 "\"dots\": 1," stipple ${WORK}/line.pgm --count 1 --method ${method} --out ${WORK}/one_${method}.svg
         --quiet)
  expect_count(${WORK}/one_${method}.svg "<circle" 1)
endforeach()
foreach(method lloyd bilateral-lloyd darts kernel)
  set(iterations --iterations 10)
  if(method STREQUAL "darts")
    set(iterations)
  endif()
  expect(stipple_${method} 0 "\"channels\": 1, \"method\": \"${method}\", \"dots\": 40, \"palette\": 1,"
         stipple ${WORK}/line.pgm --count 40 --method ${method} ${iterations} --out ${WORK}/st_${method}.svg
         --png ${WORK}/st_${method}.png --quiet)
  expect_count(${WORK}/st_${method}.svg "<circle" 40)
endforeach()
expect(stipple_again 0 "\"dots\": 40" stipple ${WORK}/line.pgm --count 40 --method kernel --iterations 10
       --out ${WORK}/st_kernel2.svg --quiet)
expect_same_file(${WORK}/st_kernel.svg ${WORK}/st_kernel2.svg "stipple: the same seed gave different dots")
expect(stipple_rgb 0 "\"channels\": 3,.*\"dots\": 6, \"palette\": 3," stipple ${WORK}/tiny.ppm --count 6 --palette 3
       --method bilateral-lloyd --out ${WORK}/st_rgb.svg --quiet)
expect_count(${WORK}/st_rgb.svg "<g fill=" 3)
expect(stipple_no_image 2 "give the picture to stipple" stipple --count 5 --out ${WORK}/x.svg)
expect(stipple_bad_method 2 "--method must be lloyd, bilateral-lloyd, darts or kernel, got 'cvt'" stipple ${WORK}/line.pgm
       --count 5 --method cvt --out ${WORK}/x.svg)
expect(stipple_needs_count 2 "missing required option --count" stipple ${WORK}/line.pgm --out ${WORK}/x.svg)
expect(stipple_svg_only 2 "--out writes an SVG picture" stipple ${WORK}/line.pgm --count 5 --out ${WORK}/x.txt)
expect(stipple_too_many 2 "--count 5000 exceeds the 2304 pixels" stipple ${WORK}/line.pgm --count 5000 --out ${WORK}/x.svg)
file(WRITE ${WORK}/white.pgm "P2\n2 2\n255\n255 255 255 255\n")
# A white picture is degenerate, not an error: no dot, an empty picture and a warning (it was refused).
foreach(method lloyd darts)
  expect(stipple_white_${method} 0 "\"dots\": 0,.*white everywhere: no dot to place" stipple ${WORK}/white.pgm --count 2 --method ${method} --out ${WORK}/white.svg --png ${WORK}/white.png)
  expect_count(${WORK}/white.svg "<circle" 0)
endforeach()
# Darts put no dot on white and fill a uniformly dark square evenly: a 100 x 100 picture, black in [30, 70)^2.
# Every pixel was a candidate (white ones with the widest disc) and random visits left holes: 5-11 of 200 dots
# on white, 0 to 21 in the square's 10 x 10 cells.
set(square "P2\n100 100\n255\n")
foreach(row RANGE 99)
  set(line "")
  foreach(column RANGE 99)
    if(row GREATER_EQUAL 30 AND row LESS 70 AND column GREATER_EQUAL 30 AND column LESS 70)
      string(APPEND line "0 ")
    else()
      string(APPEND line "255 ")
    endif()
  endforeach()
  string(APPEND square "${line}\n")
endforeach()
file(WRITE ${WORK}/square.pgm "${square}")
foreach(seed 1 2 3)
  expect(stipple_darts_square_${seed} 0 "\"dots\": 200," stipple ${WORK}/square.pgm --count 200 --method darts --seed ${seed} --out ${WORK}/square.svg --quiet)
  file(READ ${WORK}/square.svg square_svg)
  string(REGEX MATCHALL "cx=\"[0-9.]+\" cy=\"[0-9.]+\"" square_dots "${square_svg}")
  set(square_outside 0)
  set(square_cells "")
  foreach(dot ${square_dots})
    string(REGEX MATCH "cx=\"([0-9]+)[.0-9]*\" cy=\"([0-9]+)" _ "${dot}")
    set(x ${CMAKE_MATCH_1})
    set(y ${CMAKE_MATCH_2})
    if(x LESS 30 OR x GREATER_EQUAL 70 OR y LESS 30 OR y GREATER_EQUAL 70)
      math(EXPR square_outside "${square_outside} + 1")
    else()
      math(EXPR cell "(${x} - 30) / 10 * 4 + (${y} - 30) / 10")
      list(APPEND square_cells ${cell})
    endif()
  endforeach()
  if(NOT square_outside EQUAL 0)
    message(SEND_ERROR "stipple_darts_square_${seed}: ${square_outside} dots on white")
  endif()
  foreach(cell RANGE 15)  # 12.5 dots a cell on average
    set(in_cell ${square_cells})
    list(FILTER in_cell INCLUDE REGEX "^${cell}$")
    list(LENGTH in_cell n)
    if(n LESS 6 OR n GREATER 20)
      message(SEND_ERROR "stipple_darts_square_${seed}: cell ${cell} of the square holds ${n} dots")
    endif()
  endforeach()
endforeach()
# A --gamma so large that every darkness underflows to 0 is named (the picture was said to be white); darts report
# no reason to stop (null, not an empty string).
expect(stipple_gamma_underflow 2 "--gamma 1e\\+300 makes the darkness of every pixel of .*line.pgm underflow to 0" stipple ${WORK}/line.pgm --count 5 --gamma 1e300 --out ${WORK}/x.svg)
file(WRITE ${WORK}/two_dark.pgm "P2\n4 4\n255\n255 255 255 255\n255 0 255 255\n255 255 255 0\n255 255 255 255\n")
expect(stipple_more_than_ink 2 "--count 3 exceeds the 2 pixels of .*two_dark.pgm with any darkness \\(of 16\\)" stipple ${WORK}/two_dark.pgm --count 3 --method kernel --out ${WORK}/x.svg)
expect(stipple_as_many_as_ink 0 "\"dots\": 2," stipple ${WORK}/two_dark.pgm --count 2 --out ${WORK}/x.svg --quiet)
expect(stipple_lloyd_sigma 2 "--sigma-feature does not apply to --method lloyd" stipple ${WORK}/line.pgm --count 5 --sigma-feature 0.2 --out ${WORK}/x.svg)
expect(stipple_darts_iterations 2 "--iterations does not apply to --method darts" stipple ${WORK}/line.pgm --count 5 --method darts --iterations 3 --out ${WORK}/x.svg)
expect(stipple_darts_stop 0 "\"method\": \"darts\", .*\"stop\": null," stipple ${WORK}/line.pgm --count 5 --method darts --out ${WORK}/x.svg --quiet)
# stipple --periodic (Lloyd only): the picture is a tile. One dot on a uniform 8 x 2 picture stays where it
# starts, a pixel centre (x, y) (its torus cell is the whole tile, centred on it); its radius is half the
# hexagonal spacing, sqrt(32 / sqrt(3)) / 2 = 2.149, more than the height: it is drawn at the copies shifted by
# 0 and +-2 in y (+-4 reach no further) and by +-8 in x where those reach into the picture (x < 2.149: +8;
# x > 5.851: -8).
file(WRITE ${WORK}/flat8x2.pgm "P2\n8 2\n255\n128 128 128 128 128 128 128 128\n128 128 128 128 128 128 128 128\n")
# Seeds 0, 1 and 4 start it at x = 1.5, 5.5 and 6.5.
foreach(seed 0 1 4)
  expect(stipple_periodic_one_${seed} 0 "\"dots\": 1, .*\"periodic\": true, .*\"dot_radius\": 2\\.149" stipple ${WORK}/flat8x2.pgm --count 1 --periodic --seed ${seed} --out ${WORK}/tile1_${seed}.svg --png ${WORK}/tile1_${seed}.ppm --quiet)
  file(READ ${WORK}/tile1_${seed}.svg tile1)
  # The dot itself comes first (Lloyd's centroid may differ from the centre in the last bits).
  string(REGEX MATCH "<circle cx=\"([0-9])\\.[0-9]+\" cy=\"([01])\\.[0-9]+\"" first "${tile1}")
  if(NOT first)
    message(SEND_ERROR "stipple_periodic_one_${seed}: the first circle is not the dot in the picture:\n${tile1}")
  else()
    set(column ${CMAKE_MATCH_1})
    set(left 0)
    set(right 0)
    if(column LESS 2)
      set(right 3)
    endif()
    if(column GREATER 5)
      set(left 3)
    endif()
    math(EXPR columns "1 + (${left} + ${right}) / 3")
    math(EXPR circles "3 * ${columns}")
    expect_count(${WORK}/tile1_${seed}.svg "<circle " ${circles})
    expect_count(${WORK}/tile1_${seed}.svg "cy=\"-[01]\\." ${columns})  # y - 2
    expect_count(${WORK}/tile1_${seed}.svg "cy=\"[23]\\." ${columns})  # y + 2
    expect_count(${WORK}/tile1_${seed}.svg "cx=\"-" ${left})  # x - 8
    expect_count(${WORK}/tile1_${seed}.svg "cx=\"(8|9|1[0-5])\\." ${right})  # x + 8
  endif()
endforeach()
# The picture is the torus's: with the dot at (1.5, 0.5), pixels 3 and 7 of the first row are both 2 from it
# (pixel 7 across the edge) and covered alike; without the copies pixel 7 was white.
file(READ ${WORK}/tile1_0.ppm tile1_pixels OFFSET 11 HEX)  # after "P6\n8 2\n255\n"
string(SUBSTRING "${tile1_pixels}" 18 6 pixel3)
string(SUBSTRING "${tile1_pixels}" 42 6 pixel7)
if(NOT pixel7 STREQUAL pixel3 OR pixel7 STREQUAL "ffffff")
  message(SEND_ERROR "stipple_periodic_one_0: pixels 3 and 7 of the first row are ${pixel3} and ${pixel7}")
endif()
# Without it the same dot is drawn once; with another method --periodic is refused.
expect(stipple_not_periodic 0 "\"dots\": 1, .*\"periodic\": false," stipple ${WORK}/flat8x2.pgm --count 1 --out ${WORK}/tile0.svg --quiet)
expect_count(${WORK}/tile0.svg "<circle " 1)
foreach(method bilateral-lloyd darts kernel)
  expect(stipple_periodic_${method} 2 "--periodic applies to --method lloyd only" stipple ${WORK}/line.pgm --count 5 --method ${method} --periodic --out ${WORK}/x.svg)
endforeach()
# bilateral-filter: every sampling and mode meets the budget and writes a picture of the input's size; the same
# seed gives the same picture; the exact filter scores null PSNR (equal) and SSIM 1; bad arguments explained.
expect(bilateral_filter_help 0 "usage: featurerecon bilateral-filter IMAGE" bilateral-filter --help)
foreach(sampling uniform bilateral)
  foreach(mode local global)
    expect(bilateral_filter_${sampling}_${mode} 0
           "\"channels\": 1, \"sampling\": \"${sampling}\", \"mode\": \"${mode}\", \"budget\": 0.5, \"taps_per_kernel_pixel\": 0\\.(49|50|51).*\"psnr_db\": ([0-9.]+|null), \"ssim\": (0\\.9|1)"
           bilateral-filter ${WORK}/line.pgm --sampling ${sampling} --mode ${mode} --budget 0.5 --out ${WORK}/bf_${sampling}_${mode}.pgm
           --quiet)
    file(READ ${WORK}/bf_${sampling}_${mode}.pgm header LIMIT 9)
    if(NOT header MATCHES "^P5\n48 48")
      message(SEND_ERROR "bilateral-filter ${sampling} ${mode}: the picture is not a 48 x 48 PGM: '${header}'")
    endif()
  endforeach()
endforeach()
expect(bilateral_filter_again 0 "\"budget\": 0.5" bilateral-filter ${WORK}/line.pgm --mode local --out ${WORK}/bf_again.pgm --budget 0.5 --quiet)
expect_same_file(${WORK}/bf_bilateral_local.pgm ${WORK}/bf_again.pgm "bilateral-filter: the same seed gave a different picture")
expect(bilateral_filter_exact 0 "\"sampling\": \"exact\",.*\"taps_per_kernel_pixel\": 1,.*\"psnr_db\": null, \"ssim\": 1,"
       bilateral-filter ${WORK}/tiny.ppm --sampling exact --out ${WORK}/bf_exact.png --exact-out ${WORK}/bf_exact2.ppm --quiet)
expect(bilateral_filter_rgb 0 "\"channels\": 3,.*\"radius\": 2," bilateral-filter ${WORK}/tiny.ppm --sigma-spatial 1
       --sigma-range 0.3 --budget 2 --out ${WORK}/bf_rgb.png --quiet)
expect(bilateral_filter_no_image 2 "give the picture to filter" bilateral-filter --out ${WORK}/x.png)
# Options the chosen sampling does not have are refused, not ignored (the exact filter printed budget 1 for
# --budget 3; uniform taps took --sampling-sigma and --no-compensation without effect).
expect(bilateral_filter_exact_budget 2 "--budget does not apply to --sampling exact \\(every pixel of the window is a tap\\)" bilateral-filter ${WORK}/tiny.ppm --sampling exact --budget 3 --out ${WORK}/x.png)
expect(bilateral_filter_exact_mode 2 "--mode does not apply to --sampling exact" bilateral-filter ${WORK}/tiny.ppm --sampling exact --mode local --out ${WORK}/x.png)
expect(bilateral_filter_uniform_sigma 2 "--sampling-sigma does not apply to --sampling uniform" bilateral-filter ${WORK}/tiny.ppm --sampling uniform --sampling-sigma 0.2 --out ${WORK}/x.png)
expect(bilateral_filter_uniform_compensation 2 "--no-compensation does not apply to --sampling uniform" bilateral-filter ${WORK}/tiny.ppm --sampling uniform --no-compensation --out ${WORK}/x.png)
expect(bilateral_filter_bad_sampling 2 "--sampling must be uniform, bilateral or exact, got 'random'"
       bilateral-filter ${WORK}/line.pgm --sampling random --out ${WORK}/x.png)
expect(bilateral_filter_bad_mode 2 "--mode must be local or global, got 'tiled'" bilateral-filter ${WORK}/line.pgm --mode tiled --out ${WORK}/x.png)
expect(bilateral_filter_budget 2 "--budget must be in \\(0, 16\\] taps per kernel pixel, got 20" bilateral-filter ${WORK}/line.pgm --budget 20 --out ${WORK}/x.png)
expect(bilateral_filter_zero_budget 2 "--budget must be > 0" bilateral-filter ${WORK}/line.pgm --budget 0 --out ${WORK}/x.png)
expect(bilateral_filter_needs_out 2 "give --out FILE.png" bilateral-filter ${WORK}/line.pgm)
expect(bilateral_filter_out_format 2 "pictures are written as PNG, JPEG, PGM or PPM, got '.*x.svg'" bilateral-filter ${WORK}/line.pgm --out ${WORK}/x.svg)
expect(bilateral_filter_missing 1 "no_such.png" bilateral-filter ${WORK}/no_such.png --out ${WORK}/x.png)
expect(sample_image_continuous_radius 2 "--method continuous needs --radius R" sample-image --input ${WORK}/line.pgm --method continuous --count 5 --out ${WORK}/x.txt)
expect(sample_image_too_many 2 "--count 13 exceeds the 12 pixels" sample-image --input ${WORK}/tiny.ppm --count 13 --out ${WORK}/x.txt)
expect(sample_image_no_output 2 "give at least one of --out" sample-image --input ${WORK}/line.pgm --count 5)
expect(sample_image_missing 1 "no_such.png" sample-image --input ${WORK}/no_such.png --count 5 --out ${WORK}/x.txt)
# Scales outside the library's range are bad arguments (status 2, naming the option), found before the input is
# read (they exited with 1, naming the library's field, some after normal estimation).
expect(sigma_feature_tiny 2 "--sigma-feature must be a scale in \\[1e-150, 1e150\\], got '1e-160'" sample --input ${WORK}/blank_first.xyz --method darts --count 2 --sigma-feature 1e-160 --out ${WORK}/o.xyz)
expect(sigma_position_huge 2 "--sigma-position must be a scale in \\[1e-150, 1e150\\], got '1e300'" sample --input ${WORK}/no_such.xyz --count 2 --sigma-position 1e300 --out ${WORK}/o.xyz)
expect(sigma_spatial_large 2 "--sigma-spatial must be at most 2048 without --radius" bilateral-filter ${WORK}/line.pgm --sigma-spatial 5000 --out ${WORK}/bf.png)
expect(sigma_range_tiny 2 "--sigma-range must be a scale in \\[1e-150, 1e150\\]" bilateral-filter ${WORK}/line.pgm --sigma-range 1e-300 --out ${WORK}/bf.png)
# PGM/PPM readers: every header field and ASCII value a plain integer, the size checked against the file before
# any allocation, binary values above the maximum refused.
file(WRITE ${WORK}/word.pgm "P2\nabc 2\n255\n1 2\n3 4\n")
expect(pgm_word_width 1 "word.pgm: bad PGM/PPM header: the width must be a positive integer, got 'abc'" sample-image --input ${WORK}/word.pgm --count 1 --out ${WORK}/o.txt)
file(WRITE ${WORK}/exp.pgm "P2\n2 1e5\n255\n1 2\n")
expect(pgm_exponent 1 "the height must be a positive integer, got '1e5'" sample-image --input ${WORK}/exp.pgm --count 1 --out ${WORK}/o.txt)
file(WRITE ${WORK}/value.pgm "P2\n2 1\n255\n1 12abc\n")
expect(pgm_value_suffix 1 "pixel value 1 '12abc' is not an integer in \\[0, 255\\]" sample-image --input ${WORK}/value.pgm --count 1 --out ${WORK}/o.txt)
file(WRITE ${WORK}/huge.pgm "P2\n99999999 99999999\n255\n1\n")
expect(pgm_huge_header 1 "huge.pgm: truncated pixel data: a 99999999x99999999 P2 image needs" sample-image --input ${WORK}/huge.pgm --count 1 --out ${WORK}/o.txt)
# A truncated JPEG (bilateral-filter writes one) is an error, not a picture padded with grey.
expect(jpeg_written 0 "\"channels\": 1" bilateral-filter ${WORK}/line.pgm --out ${WORK}/line.jpg --quiet)
execute_process(COMMAND head -c 400 ${WORK}/line.jpg OUTPUT_FILE ${WORK}/cut.jpg)
expect(jpeg_truncated 1 "cut.jpg: not a readable JPEG" sample-image --input ${WORK}/cut.jpg --count 1 --out ${WORK}/o.txt)
# Audit of the command line (mutation testing of src/cli): each audit_ test pins a property the help or the
# README promises that no earlier test checked.
# sample-image: --count >= 1, darts need M or R, --svg is SVG and --mosaic a raster picture; --count may be every
# pixel, and the mosaic of every pixel is the picture itself (PSNR null: equal), which only --mosaic reports;
# samples sit at pixel centres with their values in [0, 1] (white is 1); --radius is elimination's r_max.
expect(audit_image_count_zero 2 "--count must be >= 1, got 0" sample-image --input ${WORK}/line.pgm --count 0 --out ${A}/s.txt)
expect(audit_image_darts_nothing 2 "--method darts needs --count M or --radius R" sample-image --input ${WORK}/line.pgm --method darts --out ${A}/s.txt)
expect(audit_image_svg_extension 2 "--svg writes an SVG picture: give a file ending in \\.svg, got '.*s\\.png'" sample-image --input ${WORK}/line.pgm --count 5 --svg ${A}/s.png)
expect(audit_image_mosaic_extension 2 "--mosaic writes a raster picture: give a file ending in \\.png, \\.jpg, \\.jpeg, \\.pgm or \\.ppm, got '.*m\\.svg'" sample-image --input ${WORK}/line.pgm --count 5 --mosaic ${A}/m.svg)
expect(audit_image_every_pixel 0 "\"samples\": 12, .*\"mosaic_psnr_db\": null}" sample-image --input ${WORK}/tiny.ppm --count 12 --mosaic ${A}/m.ppm --quiet)
expect(audit_image_no_mosaic 0 "\"samples\": 12, " sample-image --input ${WORK}/tiny.ppm --count 12 --out ${A}/s.txt --quiet)
if(last_output MATCHES "mosaic_psnr_db")
  message(SEND_ERROR "audit_image_no_mosaic: mosaic_psnr_db without --mosaic: ${last_output}")
endif()
file(WRITE ${A}/white1.pgm "P2\n1 1\n255\n255\n")
expect(audit_image_white 0 "\"samples\": 1," sample-image --input ${A}/white1.pgm --count 1 --out ${A}/w.txt --quiet)
expect_count(${A}/w.txt "^0\\.5 0\\.5 1\n$" 1)
expect(audit_image_elimination_radius 0 "\"method\": \"elimination\", \"samples\": 50, \"radius\": 3," sample-image --input ${WORK}/line.pgm --count 50 --radius 3 --out ${A}/s.txt --quiet)
# stipple: kernel relaxation runs 100 steps by default, Lloyd 50; at most 10^6; RGB palettes have 6 colours by
# default, at most 64; the SVG is on white; Lloyd has no feature scale (null); dart dots sit at pixel centres;
# --count beyond the pixels is said as such; a dot's radius is at least half a pixel; darkness is 1 - luma (BT.601:
# red 0.299, blue 0.114), so two red pixels, one blue and one white give dots of radius 0.8634.
expect(audit_stipple_kernel_default 0 "\"method\": \"kernel\", .*\"iterations\": 100, \"stop\": \"iteration_cap\"" stipple ${WORK}/line.pgm --count 40 --method kernel --out ${A}/k.svg --quiet)
expect(audit_stipple_iterations_large 2 "--iterations must be in \\[0, 1000000\\], got 1000001" stipple ${WORK}/line.pgm --count 4 --iterations 1000001 --out ${A}/x.svg)
expect(audit_stipple_palette_default 0 "\"channels\": 3, \"method\": \"lloyd\", \"dots\": 6, \"palette\": 6, \"sigma_feature\": null," stipple ${WORK}/tiny.ppm --count 6 --out ${A}/t.svg --quiet)
expect_count(${A}/t.svg "<rect width=\"100%\" height=\"100%\" fill=\"#ffffff\"/>" 1)
expect(audit_stipple_palette_large 2 "--palette must be between 1 and 64 colours, got 65" stipple ${WORK}/tiny.ppm --count 6 --palette 65 --out ${A}/x.svg)
expect(audit_stipple_darts_centres 0 "\"dots\": 40," stipple ${WORK}/line.pgm --count 40 --method darts --out ${A}/d.svg --quiet)
expect_count(${A}/d.svg "<circle cx=\"[0-9]+\\.5\" cy=\"[0-9]+\\.5\"" 40)
expect(audit_stipple_count_pixels 2 "--count 17 exceeds the 16 pixels of [^\n]*two_dark.pgm\n" stipple ${WORK}/two_dark.pgm --count 17 --out ${A}/x.svg)
file(WRITE ${A}/light.pgm "P2\n10 10\n255\n")
string(REPEAT "200 " 99 audit_light)
file(APPEND ${A}/light.pgm "${audit_light}0\n")
expect(audit_stipple_least_dot 0 "\"dots\": 100, .*\"dot_radius\": 0.5," stipple ${A}/light.pgm --count 100 --method darts --out ${A}/l.svg --quiet)
file(WRITE ${A}/rbw.ppm "P3\n2 2\n255\n255 0 0 255 0 0\n0 0 255 255 255 255\n")
expect(audit_stipple_luma 0 "\"dots\": 1, .*\"dot_radius\": 0\\.8634" stipple ${A}/rbw.ppm --count 1 --method darts --out ${A}/r.svg --quiet)
# bilateral-filter: --radius in [1, 4096], --candidates in [2, 64], --sigma-spatial at most 2048 without --radius,
# --exact-out a picture too; the exact filter reports its mode as exact; density compensation is on for bilateral
# taps (default) and off for uniform ones; --exact-out holds the exact filter (the --sampling exact picture); values
# are rounded: 0 and 255 averaged with (nearly) equal weights give 127 and 128.
expect(audit_filter_radius_zero 2 "--radius must be between 1 and 4096 pixels, got 0" bilateral-filter ${WORK}/line.pgm --radius 0 --out ${A}/f.png)
expect(audit_filter_candidates_one 2 "--candidates must be between 2 and 64 per tap, got 1" bilateral-filter ${WORK}/line.pgm --candidates 1 --out ${A}/f.png)
expect(audit_filter_sigma_spatial 2 "--sigma-spatial must be at most 2048 without --radius" bilateral-filter ${WORK}/line.pgm --sigma-spatial 3000 --out ${A}/f.png)
expect(audit_filter_exact_out_format 2 "pictures are written as PNG, JPEG, PGM or PPM, got '.*e\\.svg'" bilateral-filter ${WORK}/line.pgm --out ${A}/f.png --exact-out ${A}/e.svg)
expect(audit_filter_compensation 0 "\"sampling\": \"bilateral\", .*\"density_compensation\": true, .*\"psnr_db\": [0-9]" bilateral-filter ${WORK}/tiny.ppm --budget 0.5 --out ${A}/f.ppm --exact-out ${A}/fe.ppm --quiet)
expect(audit_filter_uniform 0 "\"sampling\": \"uniform\", .*\"density_compensation\": false," bilateral-filter ${WORK}/line.pgm --sampling uniform --budget 0.5 --out ${A}/u.pgm --quiet)
expect(audit_filter_exact 0 "\"sampling\": \"exact\", \"mode\": \"exact\", \"budget\": 1," bilateral-filter ${WORK}/tiny.ppm --sampling exact --out ${A}/x.ppm --quiet)
expect_same_file(${A}/fe.ppm ${A}/x.ppm "audit_filter_exact: --exact-out is not the exact filter")
file(WRITE ${A}/bw.pgm "P2\n2 1\n255\n0 255\n")
expect(audit_filter_rounding 0 "\"radius\": 1," bilateral-filter ${A}/bw.pgm --sampling exact --radius 1 --sigma-spatial 1000 --sigma-range 1e6 --out ${A}/bw_out.pgm --quiet)
file(READ ${A}/bw_out.pgm audit_bw HEX)
if(NOT audit_bw MATCHES "7f80$")
  message(SEND_ERROR "audit_filter_rounding: the filtered values are not 127 and 128: ${audit_bw}")
endif()
# sample-image --picture is the SVG's drawing as a raster: the same mid-grey background (#8c8c8c).
expect(audit_image_picture_background 0 "\"samples\": 5," sample-image --input ${WORK}/line.pgm --count 5 --svg ${A}/p.svg --picture ${A}/p.ppm --quiet)
expect_count(${A}/p.svg "<rect width=\"100%\" height=\"100%\" fill=\"#8c8c8c\"/>" 1)
file(READ ${A}/p.ppm audit_picture HEX)
string(REGEX MATCHALL "8c8c8c8c8c8c8c8c8c" audit_grey "${audit_picture}")
list(LENGTH audit_grey audit_grey)
if(audit_grey LESS 100)
  message(SEND_ERROR "audit_image_picture_background: the picture's background is not the SVG's grey")
endif()
# The mosaic gives every pixel its nearest sample's colour, a tie to the first sample (as --out lists them):
# darts at 1.5 on red, green, blue keep red and blue, and green's pixel, 1 from each, turns red.
file(WRITE ${A}/rgb3.ppm "P3\n3 1\n255\n255 0 0 0 255 0 0 0 255\n")
expect(audit_mosaic_tie 0 "\"samples\": 2," sample-image --input ${A}/rgb3.ppm --method darts --radius 1.5 --out ${A}/rgb3.txt --mosaic ${A}/rgb3_mosaic.ppm --quiet)
expect_count(${A}/rgb3.txt "^0\\.5 0\\.5 1 0 0\n2\\.5 0\\.5 0 0 1\n$" 1)
file(READ ${A}/rgb3_mosaic.ppm audit_mosaic HEX)
if(NOT audit_mosaic MATCHES "ff0000ff00000000ff$")
  message(SEND_ERROR "audit_mosaic_tie: the tied pixel is not the first sample's red: ${audit_mosaic}")
endif()
