# cmake -DTOOL=path/to/massprops -DHELP2MAN=path/to/help2man -DOUTPUT=man/massprops.1 -P man_page.cmake
# Writes the man page massprops.1 (and massprops.1.gz, as Debian installs it) with help2man from
# the tool's own --help and --version. help2man reads only the top-level --help, so a COMMANDS
# section with each subcommand's --help (its usage, arguments and options) is given to it as an
# --include file; the subcommands are those the top-level --help lists, so a new one appears
# without a change here.
cmake_minimum_required(VERSION 3.16)

# Text of the tool's --help for the words in `args`; fails the build when the tool does.
function(tool_help out)
  execute_process(COMMAND "${TOOL}" ${ARGN} --help OUTPUT_VARIABLE text RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "`${TOOL} ${ARGN} --help` failed (${rc})")
  endif()
  set(${out} "${text}" PARENT_SCOPE)
endfunction()

# roff-escapes a line of text: backslashes, and a leading '.' or '\'' that roff reads as a request.
function(roff_escape out line)
  string(REPLACE "\\" "\\e" line "${line}")
  if(line MATCHES "^[.']")
    set(line "\\&${line}")
  endif()
  set(${out} "${line}" PARENT_SCOPE)
endfunction()

# The subcommands: the lines of the "Subcommands:" block of the top-level help ("  NAME  text").
tool_help(top)
string(REPLACE ";" "\\;" top "${top}")
string(REPLACE "\n" ";" top_lines "${top}")
set(commands "")
set(in_block OFF)
foreach(line IN LISTS top_lines)
  if(line MATCHES "^[A-Za-z].*:$")
    string(TOUPPER "${line}" heading)
    set(in_block OFF)
    if(heading STREQUAL "SUBCOMMANDS:")
      set(in_block ON)
    endif()
  elseif(in_block AND line MATCHES "^  +([a-z][a-z-]*)( |$)")
    list(APPEND commands "${CMAKE_MATCH_1}")
  endif()
endforeach()
if(NOT commands)
  message(FATAL_ERROR "no subcommand found in `${TOOL} --help`")
endif()

# One .SS per subcommand: its help, with each option or argument as a tagged paragraph.
set(include "[COMMANDS]\n")
string(APPEND include "Each command's own help (\\fBmassprops \\fICOMMAND\\fB \\-\\-help\\fR).\n")
foreach(command IN LISTS commands)
  tool_help(text ${command})
  string(REPLACE ";" "\\;" text "${text}")
  string(REPLACE "\n" ";" lines "${text}")
  string(APPEND include ".SS \"massprops ${command}\"\n")
  foreach(line IN LISTS lines)
    if(line MATCHES "^ *$")
      continue()
    elseif(line MATCHES "^  +(-?[^ ].*[^ ]|[^ ])   *([^ ].*)$")
      # "  --option TYPE   Description": the option in bold, its text indented below.
      set(option "${CMAKE_MATCH_1}")
      roff_escape(description "${CMAKE_MATCH_2}")
      roff_escape(option "${option}")
      string(REPLACE "-" "\\-" option "${option}")
      string(APPEND include ".TP\n\\fB${option}\\fR\n${description}\n")
    elseif(line MATCHES "^  +([^ ].*)$")
      # An option without description, or a continued description.
      roff_escape(rest "${CMAKE_MATCH_1}")
      if(rest MATCHES "^-")
        string(REPLACE "-" "\\-" rest "${rest}")
        string(APPEND include ".TP\n\\fB${rest}\\fR\n")
      else()
        string(APPEND include "${rest}\n")
      endif()
    elseif(line MATCHES "^[A-Za-z].*:$")
      roff_escape(heading "${line}")
      string(APPEND include ".PP\n\\fB${heading}\\fR\n")
    else()
      roff_escape(paragraph "${line}")
      string(APPEND include ".PP\n${paragraph}\n")
    endif()
  endforeach()
endforeach()
file(WRITE "${OUTPUT}.h2m" "${include}")

execute_process(COMMAND "${HELP2MAN}" --no-info --no-discard-stderr --section=1
                        "--name=validate and repair robot mass properties (URDF, SDF)"
                        "--include=${OUTPUT}.h2m" "--output=${OUTPUT}" "${TOOL}"
                RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "help2man failed (${rc})")
endif()
# Debian installs man pages gzipped, with no name or time stamp in the header (gzip -n).
execute_process(COMMAND gzip -9 -n -f -k "${OUTPUT}" RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "gzip of ${OUTPUT} failed (${rc})")
endif()
