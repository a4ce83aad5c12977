# Golden-mesh check of one input under one kernel: runs quad-mesher at every stage in STAGES,
# hashes each written mesh (SHA-256 of the MSH file) and compares it with the lines of LIST
# that name this case and kernel. The lines this run would give are written to ACTUAL, which
# regenerate.sh gathers into a new list.
#
#   cmake -DCLI=quad-mesher -DINPUT=in.poly -DCASE=name -DKERNEL=epick "-DSTAGES=quadtree;points"
#         [-DOPTIONS=--curves;spline] -DLIST=golden.txt -DACTUAL=out.txt -DWORK_DIR=dir
#         -P check_golden.cmake
#
# A list line is `CASE KERNEL STAGE SHA256`.

foreach(var CLI INPUT CASE KERNEL STAGES LIST ACTUAL WORK_DIR)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "check_golden.cmake: ${var} is not set")
  endif()
endforeach()

file(MAKE_DIRECTORY "${WORK_DIR}")
set(expected_lines "")
if(EXISTS "${LIST}")
  file(STRINGS "${LIST}" expected_lines REGEX "^${CASE} ${KERNEL} ")
endif()

set(actual "")
set(failures "")
foreach(stage IN LISTS STAGES)
  set(mesh "${WORK_DIR}/${CASE}_${KERNEL}_${stage}.msh")
  file(REMOVE "${mesh}")
  execute_process(
    COMMAND "${CLI}" "${INPUT}" --kernel ${KERNEL} --stop-after ${stage} ${OPTIONS} -o "${mesh}"
    RESULT_VARIABLE status OUTPUT_QUIET ERROR_VARIABLE errors)
  if(NOT status EQUAL 0 AND NOT status EQUAL 4) # 4: written, with unforced angles out
    list(APPEND failures "${stage}: quad-mesher exited ${status}: ${errors}")
    continue()
  endif()
  file(SHA256 "${mesh}" hash)
  string(APPEND actual "${CASE} ${KERNEL} ${stage} ${hash}\n")
  set(want "")
  foreach(line IN LISTS expected_lines)
    if(line MATCHES "^${CASE} ${KERNEL} ${stage} ([0-9a-f]+)$")
      set(want "${CMAKE_MATCH_1}")
    endif()
  endforeach()
  if(want STREQUAL "")
    list(APPEND failures "${stage}: no golden hash in ${LIST} (mesh ${hash})")
  elseif(NOT want STREQUAL hash)
    list(APPEND failures "${stage}: mesh ${hash}, golden ${want} (${mesh})")
  endif()
endforeach()
file(WRITE "${ACTUAL}" "${actual}")

if(failures)
  string(REPLACE ";" "\n  " text "${failures}")
  message(FATAL_ERROR "golden meshes of ${CASE} (${KERNEL}) differ:\n  ${text}\n"
                      "If the change is meant to change meshes, run test/golden/regenerate.sh "
                      "and say why in the commit message.")
endif()
message(STATUS "${CASE} (${KERNEL}): every stage's mesh matches its golden hash")
