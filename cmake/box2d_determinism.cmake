# The Box2D that perpdot links must compute its collision results with the same roundings on every
# CPU: a fused multiply-add (a*b+c rounded once) gives other bits than a multiply and an add, and so
# does x87 arithmetic on 32-bit x86 (80-bit registers). Debian's amd64 libbox2d has neither; its
# arm64 build holds about 1,700 fused multiply-adds (gcc's default -ffp-contract=fast).
# third_party/box2d-deterministic.sh builds Box2D 2.4.1 from Debian's source without them.
#
#   perpdot_check_box2d(<library file> <objdump>)
#
# disassembles the library and stops the configure with the functions that hold such instructions,
# unless PERPDOT_ALLOW_NONDETERMINISTIC_BOX2D is ON. The same file runs as a script, as the ctest
# box2d_determinism_check does with an object that holds a fused multiply-add:
#
#   cmake -DLIBRARY=<file> -DOBJDUMP=<objdump> [-DX87=ON] -P cmake/box2d_determinism.cmake

if(CMAKE_SCRIPT_MODE_FILE STREQUAL CMAKE_CURRENT_LIST_FILE)
  cmake_minimum_required(VERSION 3.25)
endif()

# Instructions as objdump prints them ("<address>:<tab><mnemonic>"): aarch64 fmadd, fmsub, fnmadd,
# fnmsub, fmla, fmls (and SVE's fmad, fmsb, fnmla, ...); x86 vfmadd*, vfmsub*, vfnmadd*, vfnmsub*,
# vfmaddsub*, vfmsubadd* (FMA3 and FMA4). With X87, also x87 arithmetic (fadd, fmul, fdivr, fsqrt ...).
function(perpdot_rounding_hazards library objdump x87 outCount outReport)
  set(pattern ":[[:space:]]+(v?fn?m(add|sub)|fn?ml[as]|fn?mad|fn?msb)")
  if(x87)
    string(APPEND pattern "|:[[:space:]]+(f(add|sub|subr|mul|div|divr)[lsp]?|fi(add|sub|subr|mul|div|divr)[lsp]?|fsqrt)[[:space:]]")
  endif()
  # Count per function: "<count> <function>" lines.
  set(program "/^[0-9a-f]+ <.*>:$/ { fn = substr($0, index($0, \"<\") + 1); sub(/(@@[^>]*)?>:$/, \"\", fn) } $0 ~ /${pattern}/ { n[fn]++ } END { for (f in n) print n[f], f }")
  execute_process(COMMAND ${objdump} -d -C --no-show-raw-insn ${library}
                  COMMAND awk "${program}"
                  OUTPUT_VARIABLE lines RESULT_VARIABLE result ERROR_VARIABLE error)
  if(NOT result EQUAL 0)
    message(FATAL_ERROR "Box2D determinism check: cannot disassemble ${library} with ${objdump}: ${error}")
  endif()
  string(REPLACE ";" "," lines "${lines}")
  string(REPLACE "\n" ";" lines "${lines}")
  list(SORT lines COMPARE NATURAL ORDER DESCENDING)
  set(total 0)
  set(report "")
  set(shown 0)
  foreach(line IN LISTS lines)
    if(line MATCHES "^([0-9]+) (.*)$")
      math(EXPR total "${total} + ${CMAKE_MATCH_1}")
      math(EXPR shown "${shown} + 1")
      if(shown LESS_EQUAL 10)  # the ten functions with most
        string(APPEND report "\n    ${CMAKE_MATCH_1} in ${CMAKE_MATCH_2}")
      endif()
    endif()
  endforeach()
  set(${outCount} ${total} PARENT_SCOPE)
  set(${outReport} "${report}" PARENT_SCOPE)
endfunction()

function(perpdot_check_box2d library objdump x87)
  if(NOT objdump)
    message(FATAL_ERROR "Box2D determinism check: no objdump for the target (CMAKE_OBJDUMP) to disassemble ${library}; "
                        "install binutils for the target or pass -DPERPDOT_ALLOW_NONDETERMINISTIC_BOX2D=ON")
  endif()
  perpdot_rounding_hazards("${library}" "${objdump}" "${x87}" count report)
  if(count EQUAL 0)
    message(STATUS "Box2D determinism check: ${library} holds no fused multiply-add")
    return()
  endif()
  set(text "${library} holds ${count} instructions that round differently from other CPUs "
           "(fused multiply-adds, or x87 arithmetic on 32-bit x86), so a world would not step to the same bits "
           "on every architecture. Build Box2D without them and link it:\n"
           "    prefix=$(third_party/box2d-deterministic.sh native|aarch64|i386)\n"
           "    cmake -DPERPDOT_BOX2D_PREFIX=$prefix ...\n"
           "or give up cross-architecture determinism with -DPERPDOT_ALLOW_NONDETERMINISTIC_BOX2D=ON.\n"
           "  Functions (instructions in each):${report}")
  string(CONCAT text ${text})
  if(PERPDOT_ALLOW_NONDETERMINISTIC_BOX2D)
    message(WARNING "Box2D determinism check (PERPDOT_ALLOW_NONDETERMINISTIC_BOX2D=ON): ${text}")
  else()
    message(FATAL_ERROR "Box2D determinism check: ${text}")
  endif()
endfunction()

if(CMAKE_SCRIPT_MODE_FILE STREQUAL CMAKE_CURRENT_LIST_FILE)
  perpdot_check_box2d("${LIBRARY}" "${OBJDUMP}" "${X87}")
endif()
