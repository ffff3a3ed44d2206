# Writes OUT, a header that defines TETSMOOTH_GIT_SHA as scripts/git_version.sh
# prints it (the commit, "-dirty" when the measured code differs from it).
# bench/CMakeLists.txt runs this at every build, not once at configure time,
# so that a binary built after a commit or an edit names what it was built
# from; the header is rewritten only when that changes, and bench_smooth.cpp
# is recompiled only then.
#
#   cmake -DSOURCE_DIR=<repository> -DOUT=<header> -P git_sha.cmake
execute_process(COMMAND ${SOURCE_DIR}/scripts/git_version.sh WORKING_DIRECTORY ${SOURCE_DIR}
                OUTPUT_VARIABLE sha OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
if(sha STREQUAL "")
  set(sha unknown)
endif()
set(text "#pragma once\n// Written by bench/git_sha.cmake at build time.\n#define TETSMOOTH_GIT_SHA \"${sha}\"\n")
set(old "")
if(EXISTS ${OUT})
  file(READ ${OUT} old)
endif()
if(NOT old STREQUAL text)
  file(WRITE ${OUT} "${text}")
endif()
