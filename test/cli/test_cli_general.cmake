# SPDX-License-Identifier: GPL-3.0-or-later
# The program as a whole and the complex commands: help, argument parsing (the audit's refusals), rips
# and reeb on the figure eight, empty and degenerate input, outputs that are links, FIFOs, standard output or
# names that are no UTF-8.
# Run by ctest as cli_general with the variables of cli_common.cmake.
include(${CMAKE_CURRENT_LIST_DIR}/cli_common.cmake)

expect(help 0 "rips.*reeb" --help)
expect(rips_help 0 "usage: featurerecon rips --points FILE" rips --help)
expect(reeb_help 0 "usage: featurerecon reeb --complex" reeb --help)
expect(unknown_command 2 "unknown command 'frobnicate'" frobnicate)
# Every command name stands in its own column (evaluate-map and bilateral-filter ran into their summaries).
execute_process(COMMAND ${FEATURERECON} --help OUTPUT_VARIABLE main_help)
foreach(name rips evaluate-map bilateral-filter synthetic-city sample-image)
  string(LENGTH ${name} length)
  math(EXPR pad "18 - ${length}")
  string(REPEAT " " ${pad} spaces)
  if(NOT main_help MATCHES "\n  ${name}${spaces}[A-Z]")
    message(SEND_ERROR "main_help: the summary of '${name}' does not start in column 21:\n${main_help}")
  endif()
endforeach()
# No command: the help, as a usage error, on standard error (it went to standard output).
execute_process(COMMAND ${FEATURERECON} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 2 OR NOT out STREQUAL "" OR NOT err MATCHES "usage: featurerecon COMMAND")
  message(SEND_ERROR "no_command: exit ${rc}, standard output '${out}'")
endif()
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
expect_same_file(${WORK}/fig8.txt ${WORK}/fig8_bf.txt "kd-tree and brute-force searches wrote different complexes")

# Same input, same bytes.
expect(rips_again 0 "wrote" rips --points ${DATA}/figure_eight.xyz --radius 0.6 --out ${WORK}/fig8_again.txt --quiet)
expect_same_file(${WORK}/fig8.txt ${WORK}/fig8_again.txt "two runs on the same input wrote different complexes")

# Empty input is not an error.
file(WRITE ${WORK}/empty.xyz "# no points\n")
expect(rips_empty 0 "wrote .*empty.txt: 0 vertices.*warning: .*empty.xyz holds no points" rips --points ${WORK}/empty.xyz --radius 1 --out ${WORK}/empty.txt --quiet)
expect(skeleton_empty 0 "\"points\": 0,.*warning: the input holds no points: the skeleton is empty" skeleton --points ${WORK}/empty.xyz --radius 1 --out-vertices ${WORK}/a --out-edges ${WORK}/b --quiet)
expect(skeleton_empty_tracks 0 "\"points\": 0,.*warning: the input holds no fixes" skeleton --tracks ${WORK}/empty.xyz --out-vertices ${WORK}/a --out-edges ${WORK}/b --quiet)
expect(reeb_empty 0 "\"vertices\": 0,.*\"nodes\": 0,.*\"components\": 0" reeb --complex ${WORK}/empty.txt --json)
# One point in 5 dimensions, then duplicates.
file(WRITE ${WORK}/one.xyz "1 2 3 4 5\n")
expect(rips_one 0 "1 vertices, 0 edges.*dimension 5" rips --points ${WORK}/one.xyz --radius 1 --out ${WORK}/one.txt --quiet)
expect(reeb_one 0 "\"nodes\": 1,.*\"minima\": 1, \"maxima\": 1" reeb --complex ${WORK}/one.txt --json)
file(WRITE ${WORK}/dup.xyz "0 0\n0 0\n0 0\n3 0\n")
expect(rips_dup 0 "4 vertices, 3 edges, 1 triangles, 2 components" rips --points ${WORK}/dup.xyz --radius 0 --out ${WORK}/dup.txt --quiet)
# A complex larger than --max-triangles is refused while counting (the figure eight at 0.6 has 22,292 triangles).
expect(rips_max_triangles 1 "more than 22291 triangles \\(--max-triangles; 400 vertices, 4226 edges" rips --points ${DATA}/figure_eight.xyz --radius 0.6 --max-triangles 22291 --out ${WORK}/fig8_max.txt --quiet)
expect(rips_max_triangles_equal 0 "22292 triangles" rips --points ${DATA}/figure_eight.xyz --radius 0.6 --max-triangles 22292 --out ${WORK}/fig8_max.txt --quiet)
expect(rips_max_triangles_bad 2 "--max-triangles must be an integer >= 0 \\(0: no limit\\), got '-1'" rips --points ${DATA}/figure_eight.xyz --radius 0.6 --max-triangles -1 --out ${WORK}/fig8_max.txt --quiet)
# ... before the input is read (it was parsed after the graph was built).
expect(rips_max_triangles_first 2 "--max-triangles must be an integer" rips --points ${WORK}/no_such_points.xyz --radius 0.6 --max-triangles abc --out ${WORK}/fig8_max.txt --quiet)
expect(skeleton_max_triangles 1 "extract_reeb_skeleton: the flag complex has more than 100 triangles \\(max_triangles of the options;.*\\(on the command line: max_triangles is --max-triangles\\)" skeleton --points ${DATA}/figure_eight.xyz --radius 0.6 --max-triangles 100 --out-vertices ${WORK}/mt_v.txt --out-edges ${WORK}/mt_e.txt --quiet)
expect(skeleton_max_triangles_off 0 "\"rips_triangles\": 22292, \"max_triangles\": 0, \"isolated_points\": 0, .*\"loops\": 2," skeleton --points ${DATA}/figure_eight.xyz --radius 0.6 --max-triangles 0 --out-vertices ${WORK}/mt_v.txt --out-edges ${WORK}/mt_e.txt --quiet)

# Persistence pairs: the figure-eight has two loops, each a [birth, death] pair with birth > death.
expect(reeb_persistence 0 "\"loops\": 2,.*\"branch_pairs\": \\[.*\"loop_pairs\": \\[\\[[-0-9.e]+, [-0-9.e]+\\], \\[[-0-9.e]+, [-0-9.e]+\\]\\]}" reeb --complex ${WORK}/fig8.txt --json --persistence)
# Progress goes to standard error, under --json too (standard output is the JSON object alone); each stage
# ends with its "done" line, the persistence's with its pair counts. --quiet silences it.
expect(reeb_persistence_progress 0 "\"loop_pairs\": " reeb --complex ${WORK}/fig8.txt --json --persistence --simplify 0)
if(NOT last_error MATCHES "reeb graph: done[^\n]*\n(.*\n)?simplification: done[^\n]*\n(.*\n)?persistence: done \\([0-9]+ branch and 2 loop pairs\\)"
   OR NOT last_output MATCHES "^{[^\n]*}\n$")
  message(SEND_ERROR "reeb_persistence_progress: stages missing on stderr or more than the object on stdout:\n${last_output}\n${last_error}")
endif()
expect(reeb_persistence_quiet 0 "\"loop_pairs\": " reeb --complex ${WORK}/fig8.txt --json --persistence --quiet)
if(NOT last_error STREQUAL "")
  message(SEND_ERROR "reeb_persistence_quiet: --quiet still wrote to stderr:\n${last_error}")
endif()
expect(persistence_without_json 2 "--persistence goes with --json" reeb --complex ${WORK}/fig8.txt --persistence)

# Simplification: the figure-eight keeps its two loops at delta = 1 and loses them at delta = 20.
expect(reeb_simplify 0 "\"loops\": 2,.*\"removed_loops\": 0" reeb --complex ${WORK}/fig8.txt --json --simplify 1)
expect(reeb_simplify_all 0 "\"loops\": 0,.*\"removed_loops\": 2" reeb --complex ${WORK}/fig8.txt --json --simplify 20)
expect(reeb_simplify_negative 2 "--simplify must be >= 0" reeb --complex ${WORK}/fig8.txt --simplify -1)
# An empty value (--out=, or --out "$UNSET") is refused as a missing one, for every valued option.
expect(empty_value_inline 2 "option --out needs a value, got an empty one" stipple ${WORK}/line.pgm --count 40 --out=)
expect(empty_value_number 2 "option --radius needs a value, got an empty one" rips --points ${DATA}/figure_eight.xyz --radius= --out ${WORK}/x.txt)
# A corrupt header does not ask for 4e9 vertices of memory.
file(WRITE ${WORK}/huge_n.txt "4000000000 0\n")
expect(complex_huge_header 1 "huge_n.txt: unexpected end of file after 0 of 4000000000 vertex lines" reeb --complex ${WORK}/huge_n.txt --json)

# Outputs that are not plain files: a symbolic link is written through (the link stays, the file it points to
# gets the output), a FIFO (like /dev/null or /dev/stdout) is written in place, not replaced by a file; an output
# naming an input is refused before any work.
file(MAKE_DIRECTORY ${WORK}/special)
file(WRITE ${WORK}/special/real.cx "old\n")
# expect_written_through_link(NAME LINK TARGET): rips --out LINK writes TARGET, and LINK stays a link.
function(expect_written_through_link name link target)
  file(CREATE_LINK ${target} ${WORK}/special/${link} SYMBOLIC)
  expect(${name} 0 "wrote .*${link}: 400 vertices"
         rips --points ${DATA}/figure_eight.xyz --radius 0.6 --out ${WORK}/special/${link} --quiet)
  expect_same_file(${WORK}/special/${target} ${WORK}/fig8.txt "${name}: the file the link points to")
  if(NOT IS_SYMLINK ${WORK}/special/${link})
    message(SEND_ERROR "${name}: the symbolic link was replaced by a file")
  endif()
endfunction()
expect_written_through_link(output_through_link link.cx real.cx)
# A dangling link too: the file it names is created (the link was replaced), and a missing directory is named.
file(REMOVE ${WORK}/special/made.cx)
expect_written_through_link(output_through_dangling_link dangling.cx made.cx)
file(CREATE_LINK loop_b.cx ${WORK}/special/loop_a.cx SYMBOLIC)
file(CREATE_LINK loop_a.cx ${WORK}/special/loop_b.cx SYMBOLIC)
expect(output_through_link_loop 2 "loop_a.cx is a loop of symbolic links" rips --points ${DATA}/figure_eight.xyz --radius 0.6 --out ${WORK}/special/loop_a.cx --quiet)
if(NOT IS_SYMLINK ${WORK}/special/loop_a.cx)
  message(SEND_ERROR "output_through_link_loop: the link was replaced")
endif()
file(CREATE_LINK ${WORK}/no_such_directory/x.cx ${WORK}/special/nowhere.cx SYMBOLIC)
expect(output_through_link_nowhere 2 "the directory .*no_such_directory of .*nowhere.cx does not exist" rips --points ${DATA}/figure_eight.xyz --radius 0.6 --out ${WORK}/special/nowhere.cx --quiet)
# A file name that is no UTF-8 (Latin-1 bytes) keeps the JSON valid: the byte becomes U+FFFD.
if(BASH_PROGRAM)
  execute_process(COMMAND ${BASH_PROGRAM} -c "cd '${WORK}/special' && cp '${DATA}/figure_eight.xyz' \"$(printf 'latin\\xe9.xyz')\" && \"$0\" sample-stats --input \"$(printf 'latin\\xe9.xyz')\"" ${FEATURERECON}
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0 OR NOT out MATCHES "\"input\": \"latin\\\\ufffd\\.xyz\"")
    message(SEND_ERROR "json_non_utf8_path: exit ${rc}:\n${out}${err}")
  else()
    message(STATUS "ok: json_non_utf8_path")
  endif()
endif()
if(BASH_PROGRAM)
  execute_process(COMMAND ${BASH_PROGRAM} -c "cd '${WORK}/special' && mkfifo fifo.cx && { timeout 30 cat fifo.cx > from_fifo.cx & } && \"$0\" rips --points '${DATA}/figure_eight.xyz' --radius 0.6 --out fifo.cx --quiet && wait && test -p fifo.cx" ${FEATURERECON}
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(SEND_ERROR "output_to_fifo: exit ${rc} (the FIFO should stay a FIFO):\n${out}${err}")
  else()
    expect_same_file(${WORK}/special/from_fifo.cx ${WORK}/fig8.txt "output_to_fifo: what the reader got")
    message(STATUS "ok: output_to_fifo")
  endif()
  # An output written to standard output (/dev/stdout) sends the summary to standard error: it was appended to the complex, which the next command in the pipe then refused.
  execute_process(COMMAND ${BASH_PROGRAM} -c "\"$0\" rips --points '${DATA}/figure_eight.xyz' --radius 0.6 --out /dev/stdout --quiet 2> '${WORK}/special/rips_summary.txt' | \"$0\" reeb --complex /dev/stdin --json" ${FEATURERECON}
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  file(READ ${WORK}/special/rips_summary.txt rips_summary)
  if(NOT rc EQUAL 0 OR NOT out MATCHES "\"loops\": 2," OR NOT rips_summary MATCHES "wrote /dev/stdout: 400 vertices")
    message(SEND_ERROR "output_to_stdout_pipe: exit ${rc}:\n${out}${err}\nsummary: ${rips_summary}")
  else()
    message(STATUS "ok: output_to_stdout_pipe")
  endif()
  # Standard output redirected to a file: the output goes where the descriptor stands, between what the shell
  # wrote before and after (the file behind /dev/stdout was replaced by a new one holding the output alone).
  execute_process(COMMAND ${BASH_PROGRAM} -c "{ echo BEFORE; \"$0\" rips --points '${DATA}/figure_eight.xyz' --radius 0.6 --out /dev/stdout --quiet 2> /dev/null; echo AFTER; } > '${WORK}/special/stdout_file.txt'" ${FEATURERECON}
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  file(READ ${WORK}/special/stdout_file.txt stdout_file)
  file(READ ${WORK}/fig8.txt fig8_complex)
  if(NOT rc EQUAL 0 OR NOT stdout_file STREQUAL "BEFORE\n${fig8_complex}AFTER\n")
    message(SEND_ERROR "output_to_stdout_file: exit ${rc}:\n${err}\nthe file begins: ${stdout_file}")
  else()
    message(STATUS "ok: output_to_stdout_file")
  endif()
  # Interrupted (SIGINT, as Ctrl-C sends) while writing: no temporary is left behind. 600 copies of one point
  # make a complex of 36 M triangles, minutes of work.
  string(REPEAT "0 0\n" 600 same_points)
  file(WRITE ${WORK}/special/same.xyz "${same_points}")
  execute_process(COMMAND ${BASH_PROGRAM} -c "timeout -s INT 3 \"$0\" rips --points '${WORK}/special/same.xyz' --radius 1 --out '${WORK}/special/interrupted.cx' --quiet" ${FEATURERECON}
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  file(GLOB leftovers ${WORK}/special/.*)
  if(NOT rc EQUAL 124 OR leftovers OR EXISTS ${WORK}/special/interrupted.cx)
    message(SEND_ERROR "interrupted_output: exit ${rc} (124: stopped by timeout), left ${leftovers}\n${out}${err}")
  else()
    message(STATUS "ok: interrupted_output")
  endif()
  # Out of memory (an address-space limit of 400 MB) is said so, not std::bad_alloc, and nothing is written.
  execute_process(COMMAND ${BASH_PROGRAM} -c "ulimit -v 400000; exec \"$0\" \"$@\"" ${FEATURERECON} rips --points ${WORK}/special/same.xyz --radius 1 --out ${WORK}/special/oom.cx --quiet
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  file(GLOB leftovers ${WORK}/special/.*)
  if(NOT rc EQUAL 1 OR NOT err MATCHES "featurerecon rips: error: out of memory \\(" OR leftovers OR EXISTS ${WORK}/special/oom.cx)
    message(SEND_ERROR "out_of_memory: exit ${rc}, left ${leftovers}\n${out}${err}")
  else()
    message(STATUS "ok: out_of_memory")
  endif()
endif()
file(COPY ${DATA}/figure_eight.xyz DESTINATION ${WORK}/special)
expect(output_is_input 2 "--out-vertices: .*figure_eight.xyz is also the input --points" skeleton --points ${WORK}/special/figure_eight.xyz --radius 0.6 --out-vertices ${WORK}/special/figure_eight.xyz --out-edges ${WORK}/special/e.txt)
file(COPY ${M}_gt_crp_vertices.txt DESTINATION ${WORK}/special)
file(RENAME ${WORK}/special/chicago_gt_crp_vertices.txt ${WORK}/special/gt_v.txt)
expect(output_is_positional_input 2 "--samples-out: .*gt_v.txt is also the input .*gt_v.txt" evaluate-map ${WORK}/special/gt_v.txt ${M}_gt_crp_edges.txt ${M}_james_vertices.txt ${M}_james_edges.txt --samples-out ${WORK}/special/gt_v.txt)
# A number is no input, whatever files exist: --radius 0.6 --out 0.6 in a directory holding a file 0.6 writes it.
file(WRITE ${WORK}/special/0.6 "old\n")
execute_process(COMMAND ${FEATURERECON} rips --points ${DATA}/figure_eight.xyz --radius 0.6 --out 0.6 --quiet
                WORKING_DIRECTORY ${WORK}/special RESULT_VARIABLE number_rc ERROR_VARIABLE number_err)
file(READ ${WORK}/special/0.6 number_out LIMIT 40)
if(NOT number_rc EQUAL 0 OR NOT number_out MATCHES "^[0-9]")
  message(SEND_ERROR "output_named_like_a_number: rc ${number_rc}, ${number_err}")
endif()
# ... but an input file named like a number is still an input (the first fix let --out 12 overwrite --points 12).
configure_file(${DATA}/figure_eight.xyz ${WORK}/special/12 COPYONLY)
execute_process(COMMAND ${FEATURERECON} rips --points 12 --radius 0.3 --out 12 --quiet
                WORKING_DIRECTORY ${WORK}/special RESULT_VARIABLE number_rc ERROR_VARIABLE number_err)
if(NOT number_rc EQUAL 2 OR NOT number_err MATCHES "--out: 12 is also the input --points")
  message(SEND_ERROR "input_named_like_a_number: rc ${number_rc}, ${number_err}")
endif()
expect_same_file(${WORK}/special/12 ${DATA}/figure_eight.xyz "input_named_like_a_number: the input")

# Audit of the command line (mutation testing of src/cli): each audit_ test pins a property the help or the
# README promises that no earlier test checked.
# Bad arguments exit with status 2 and say which: an option given twice, a flag given a value, an argument too
# many, an integer with trailing characters or out of range.
expect(audit_option_twice 2 "option --radius given twice" rips --points ${DATA}/figure_eight.xyz --radius 0.6 --radius 0.7 --out ${A}/x.txt)
expect(audit_flag_with_value 2 "option --quiet takes no value" rips --points ${DATA}/figure_eight.xyz --radius 0.6 --quiet=yes --out ${A}/x.txt)
expect(audit_extra_argument 2 "unexpected argument '.*second.pgm'" stipple ${A}/first.pgm ${A}/second.pgm --count 5 --out ${A}/x.svg)
expect(audit_integer_suffix 2 "--knn must be an integer, got '3x'" rips --points ${DATA}/figure_eight.xyz --knn 3x --out ${A}/x.txt)
expect(audit_integer_range 2 "--knn must be an integer, got '99999999999999999999'" rips --points ${DATA}/figure_eight.xyz --knn 99999999999999999999 --out ${A}/x.txt)
# rips: exactly one of --radius and --knn, K >= 1; the kd-tree search goes up to 3-D only (auto: brute force above).
expect(audit_rips_no_scale 2 "give exactly one of --radius R and --knn K" rips --points ${DATA}/figure_eight.xyz --out ${A}/x.txt)
expect(audit_rips_knn_zero 2 "--knn must be an integer >= 1, got '0'" rips --points ${DATA}/figure_eight.xyz --knn 0 --out ${A}/x.txt)
file(STRINGS ${DATA}/figure_eight.xyz audit_eight REGEX "^[^#]")
list(TRANSFORM audit_eight APPEND " 0 0\n")
string(JOIN "" audit_eight_4d ${audit_eight})
file(WRITE ${A}/eight_4d.xyz "${audit_eight_4d}")
expect(audit_rips_kd_tree_4d 2 "--search kd-tree supports dimension <= 3; the points have dimension 4" rips --points ${A}/eight_4d.xyz --radius 0.6 --search kd-tree --out ${A}/x.txt)
expect(audit_rips_auto_4d 0 "wrote .*: 400 vertices, 4226 edges, 22292 triangles, 1 components \\(dimension 4\\)" rips --points ${A}/eight_4d.xyz --radius 0.6 --out ${A}/x.txt --quiet)
# rips writes the first three coordinates of each point (zero-padded): z too.
file(WRITE ${A}/z.xyz "0 0 5\n1 0 6\n")
expect(audit_rips_z 0 "wrote .*z.txt: 2 vertices, 1 edges, 0 triangles, 1 components \\(dimension 3\\)" rips --points ${A}/z.xyz --radius 2 --out ${A}/z.txt --quiet)
expect_count(${A}/z.txt "\n0 0 5 [0-9.]+\n1 0 6 [0-9.]+\n" 1)
# reeb on a Y (one minimum below an up-fork and two maxima): the counts by kind, in JSON and in text; the one
# branch pair is a maximum with the up-fork, [2, 1] (the superlevel branches count too); --simplify 0 is allowed
# (nothing removed), --simplify 5 removes the branch; augmented_arcs stays the augmented graph's count.
file(WRITE ${A}/y.txt "4 3\n0 0 0 0\n0 1 0 1\n-1 2 0 2\n1 2 0 2\n0 1\n1 2\n1 3\n")
expect(audit_reeb_y_json 0 "\"nodes\": 4, \"arcs\": 3, \"loops\": 0, \"minima\": 1, \"maxima\": 2, \"up_forks\": 1, \"down_forks\": 0, \"components\": 1, \"augmented_arcs\": 3, .*\"branch_pairs\": \\[\\[2, 1\\]\\], \"loop_pairs\": \\[\\]}" reeb --complex ${A}/y.txt --json --persistence --quiet)
expect(audit_reeb_y_text 0 "Reeb graph: 4 nodes, 3 arcs, 0 loops, 1 components\nnodes: 1 minima, 2 maxima, 1 up-forks, 0 down-forks\n" reeb --complex ${A}/y.txt --quiet)
expect(audit_reeb_simplify_zero 0 "\"nodes\": 4, .*\"simplified_by\": 0, \"removed_branches\": 0, \"removed_loops\": 0}" reeb --complex ${A}/y.txt --json --simplify 0 --quiet)
expect(audit_reeb_simplify 0 "\"nodes\": 2, \"arcs\": 1, .*\"augmented_arcs\": 3, .*\"simplified_by\": 5, \"removed_branches\": 1, \"removed_loops\": 0}" reeb --complex ${A}/y.txt --json --simplify 5 --quiet)
# Progress: each stage of rips announces itself on standard error under the name of the graph it builds.
expect(audit_rips_progress_radius 0 "wrote" rips --points ${DATA}/figure_eight.xyz --radius 0.6 --out ${A}/x.txt)
if(NOT last_error MATCHES "rips graph: done \\(4226 edges\\)" OR last_error MATCHES "knn graph")
  message(SEND_ERROR "audit_rips_progress_radius: no 'rips graph' stage:\n${last_error}")
endif()
expect(audit_rips_progress_knn 0 "wrote" rips --points ${DATA}/figure_eight.xyz --knn 5 --out ${A}/x.txt)
if(NOT last_error MATCHES "knn graph: done \\([0-9]+ edges\\)" OR last_error MATCHES "rips graph")
  message(SEND_ERROR "audit_rips_progress_knn: no 'knn graph' stage:\n${last_error}")
endif()
# /dev/fd/1 is standard output as /dev/stdout is: written through the descriptor, between what the shell wrote
# before and after (not a new file replacing the redirection's).
if(BASH_PROGRAM)
  execute_process(COMMAND ${BASH_PROGRAM} -c "{ echo BEFORE; \"$0\" rips --points '${DATA}/figure_eight.xyz' --radius 0.6 --out /dev/fd/1 --quiet 2> /dev/null; echo AFTER; } > '${A}/fd1.txt'" ${FEATURERECON}
                  RESULT_VARIABLE rc)
  file(READ ${A}/fd1.txt audit_fd1)
  file(READ ${WORK}/fig8.txt audit_fig8)
  if(NOT rc EQUAL 0 OR NOT audit_fd1 STREQUAL "BEFORE\n${audit_fig8}AFTER\n")
    message(SEND_ERROR "audit_output_to_fd1: exit ${rc}; the file begins: ${audit_fd1}")
  endif()
endif()
