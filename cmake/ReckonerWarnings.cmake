# One interface target carries the project's warning and sanitizer flags; every target of ours links it.
add_library(reckoner_warnings INTERFACE)
target_compile_options(reckoner_warnings INTERFACE
  -Wall -Wextra -Wpedantic -Wshadow -Wnon-virtual-dtor -Wold-style-cast -Wcast-align
  -Woverloaded-virtual -Wconversion -Wno-sign-conversion -Wimplicit-fallthrough)
if(RECKONER_WERROR)
  target_compile_options(reckoner_warnings INTERFACE -Werror)
endif()
if(RECKONER_SANITIZE STREQUAL "thread")
  target_compile_options(reckoner_warnings INTERFACE -fsanitize=thread -fno-omit-frame-pointer)
  target_link_options(reckoner_warnings INTERFACE -fsanitize=thread)
elseif(RECKONER_SANITIZE STREQUAL "address,undefined" OR RECKONER_SANITIZE STREQUAL "ON")
  # Every UBSan finding fatal, like ASan's (a report that only prints passes a test).
  target_compile_options(reckoner_warnings INTERFACE -fsanitize=address,undefined -fno-omit-frame-pointer
                                                     -fno-sanitize-recover=all)
  target_link_options(reckoner_warnings INTERFACE -fsanitize=address,undefined)
elseif(RECKONER_SANITIZE)
  message(FATAL_ERROR "RECKONER_SANITIZE=${RECKONER_SANITIZE}: use OFF, ON, address,undefined or thread")
endif()
if(RECKONER_FUZZ)
  target_compile_options(reckoner_warnings INTERFACE -fsanitize=fuzzer-no-link,address,undefined
                                                     -fno-sanitize-recover=all -fno-omit-frame-pointer)
  target_link_options(reckoner_warnings INTERFACE -fsanitize=address,undefined)
endif()
