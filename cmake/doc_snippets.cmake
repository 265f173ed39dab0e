# perpdot_doc_snippets(<name> <markdown>): compile every ```cpp block of a Markdown file, so the code
# a page shows cannot drift from the API. The blocks are extracted at configure time (editing the
# page re-runs CMake) into <build>/<name>/, each with a #line directive, so a compiler error names
# the page and the line. A block
#   - whose first line starts with "// Box2D" is a quote of another engine's code: skipped;
#   - with an "int main(" is a whole program: the page's Nth is the executable <name>-N, run by
#     ctest <name>_N (it exits 0 only when its outcome holds);
#   - starting with "#include" is a translation unit: compiled as it is;
#   - otherwise is statements: compiled as the body of a function with a World& world, BodyId body,
#     ShapeId shape and JointId joint, after `using namespace perpdot;` (unused locals allowed).
# Translation units and statements go into the object library <name>; all compile with the
# project's warnings and -Werror.
function(perpdot_doc_snippets name markdown)
  set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${markdown})
  file(READ ${markdown} text)
  set(outDir ${CMAKE_CURRENT_BINARY_DIR}/${name})
  set(fence "```cpp\n")
  string(LENGTH "${fence}" fenceLength)
  set(objects)
  set(programs 0)
  set(line 1)
  set(consumed 0)
  while(TRUE)
    string(FIND "${text}" "${fence}" begin)
    if(begin EQUAL -1)
      break()
    endif()
    # The first code line's number: lines before the fence, plus the fence line.
    string(SUBSTRING "${text}" 0 ${begin} before)
    string(REGEX REPLACE "[^\n]" "" newlines "${before}")
    string(LENGTH "${newlines}" skipped)
    math(EXPR line "${line} + ${skipped} + 1")
    math(EXPR codeBegin "${begin} + ${fenceLength}")
    string(SUBSTRING "${text}" ${codeBegin} -1 text)
    string(FIND "${text}" "```" end)
    if(end EQUAL -1)
      message(FATAL_ERROR "${markdown}:${line}: unterminated ```cpp block")
    endif()
    string(SUBSTRING "${text}" 0 ${end} code)
    string(SUBSTRING "${text}" ${end} -1 text)
    set(codeLine ${line})
    string(REGEX REPLACE "[^\n]" "" newlines "${code}")
    string(LENGTH "${newlines}" codeLines)
    math(EXPR line "${line} + ${codeLines}")

    set(source ${outDir}/snippet_L${codeLine}.cpp)
    set(origin "#line ${codeLine} \"${markdown}\"\n")
    if(code MATCHES "^// Box2D")
      continue()
    elseif(code MATCHES "int main\\(")
      math(EXPR programs "${programs} + 1")
      file(GENERATE OUTPUT ${source} CONTENT "${origin}${code}")
      add_executable(${name}-${programs} ${source})
      target_link_libraries(${name}-${programs} PRIVATE perpdot_core perpdot_options)
      target_compile_options(${name}-${programs} PRIVATE -Werror)
      add_test(NAME ${name}_${programs} COMMAND ${name}-${programs})
    elseif(code MATCHES "^#include")
      file(GENERATE OUTPUT ${source} CONTENT "${origin}${code}")
      list(APPEND objects ${source})
    else()
      file(GENERATE OUTPUT ${source} CONTENT "#include <iterator>
#include <optional>

#include <perpdot/perpdot.hpp>

using namespace perpdot;

void snippet_L${codeLine}([[maybe_unused]] World& world, [[maybe_unused]] BodyId body,
                          [[maybe_unused]] ShapeId shape, [[maybe_unused]] JointId joint) {
${origin}${code}}
")
      set_source_files_properties(${source} PROPERTIES COMPILE_OPTIONS "-Wno-unused-variable;-Wno-unused-but-set-variable")
      list(APPEND objects ${source})
    endif()
  endwhile()
  if(objects)
    add_library(${name} OBJECT ${objects})
    target_link_libraries(${name} PRIVATE perpdot_core perpdot_options)
    target_compile_options(${name} PRIVATE -Werror)
  endif()
endfunction()
