# cmake -DCLI=path/to/reckoner-cli -DOUTPUT=commands.h2m -P CliCommandsHelp.cmake
#
# Writes a help2man include file (docs/packaging.md, "Man pages") with a COMMANDS section: the --help of
# every command of reckoner-cli, groups opened ("chart info", "chart render", ...), found as
# tests/app/tst_cli_help.cpp finds them (the names under "Subcommands:"). The text is set verbatim.

# The names listed under "Subcommands:" in a help text (no CMake list of the text's lines: its
# brackets would join them).
function(subcommands_in help out)
  set(names "")
  string(FIND "${help}" "\nSubcommands:\n" at)
  if(at GREATER_EQUAL 0)
    math(EXPR at "${at} + 14")
    string(SUBSTRING "${help}" ${at} -1 rest)
    while(rest MATCHES "^  +([^ \n]+)[^\n]*\n?(.*)$")
      list(APPEND names "${CMAKE_MATCH_1}")
      set(rest "${CMAKE_MATCH_2}")
    endwhile()
  endif()
  set(${out} "${names}" PARENT_SCOPE)
endfunction()

# Text as roff lines between .nf and .fi: backslashes escaped, no line taken for a request.
function(roff_verbatim text out)
  string(REPLACE "\\" "\\e" text "${text}")
  string(REGEX REPLACE "(^|\n)([.'])" "\\1\\\\&\\2" text "${text}")
  string(REGEX REPLACE "\n+$" "" text "${text}")
  set(${out} ".nf\n${text}\n.fi\n" PARENT_SCOPE)
endfunction()

set(section "[COMMANDS]\n`reckoner-cli COMMAND --help` prints the same.\n")
set(queue "")
execute_process(COMMAND "${CLI}" --help OUTPUT_VARIABLE help RESULT_VARIABLE failed)
if(failed)
  message(FATAL_ERROR "${CLI} --help failed")
endif()
subcommands_in("${help}" queue)
while(queue)
  list(POP_FRONT queue command)
  string(REPLACE " " ";" words "${command}")
  execute_process(COMMAND "${CLI}" ${words} --help OUTPUT_VARIABLE help RESULT_VARIABLE failed)
  if(failed)
    message(FATAL_ERROR "${CLI} ${command} --help failed")
  endif()
  subcommands_in("${help}" subs)
  if(subs)
    # A group: its commands are opened in its place.
    set(opened "")
    foreach(s IN LISTS subs)
      list(APPEND opened "${command} ${s}")
    endforeach()
    list(PREPEND queue ${opened})
    continue()
  endif()
  roff_verbatim("${help}" text)
  string(APPEND section ".SS \"${command}\"\n${text}")
endwhile()
file(WRITE "${OUTPUT}.tmp" "${section}")
file(COPY_FILE "${OUTPUT}.tmp" "${OUTPUT}" ONLY_IF_DIFFERENT)
file(REMOVE "${OUTPUT}.tmp")
