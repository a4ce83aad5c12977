# The README's library snippet must be an exact excerpt of the example it names, so that the
# code a reader copies is code that ctest builds and runs:
#   cmake -DREADME=README.md -DEXAMPLE=examples/domain_in_code.cpp -P check_readme_snippet.cmake
# The snippet is the first ```cpp block after the heading "## The library"; its lines must be
# consecutive lines of EXAMPLE, character for character.

foreach(var README EXAMPLE)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "check_readme_snippet.cmake: ${var} is not set")
  endif()
endforeach()

file(READ "${README}" readme)
string(FIND "${readme}" "\n## The library\n" section)
if(section EQUAL -1)
  message(FATAL_ERROR "${README}: no section '## The library'")
endif()
string(SUBSTRING "${readme}" ${section} -1 readme)
string(FIND "${readme}" "\n```cpp\n" open)
if(open EQUAL -1)
  message(FATAL_ERROR "${README}: no ```cpp block in '## The library'")
endif()
math(EXPR first "${open} + 8")
string(SUBSTRING "${readme}" ${first} -1 readme)
string(FIND "${readme}" "```" close)
if(close EQUAL -1)
  message(FATAL_ERROR "${README}: the ```cpp block in '## The library' is not closed")
endif()
string(SUBSTRING "${readme}" 0 ${close} snippet)

file(READ "${EXAMPLE}" example)
string(FIND "${example}" "${snippet}" at)
# the excerpt starts at a line's start
if(NOT at EQUAL -1 AND at GREATER 0)
  math(EXPR before "${at} - 1")
  string(SUBSTRING "${example}" ${before} 1 previous)
  if(NOT previous STREQUAL "\n")
    set(at -1)
  endif()
endif()
if(at EQUAL -1)
  message(FATAL_ERROR "the library snippet of ${README} is not an excerpt of ${EXAMPLE}; "
                      "copy the example's lines into the README (or the README's into the example):\n${snippet}")
endif()
message(STATUS "the library snippet of ${README} is lines of ${EXAMPLE}")
