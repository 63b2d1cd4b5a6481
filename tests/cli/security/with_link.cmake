# Security probe with a dangling symbolic link: creates OUT_DIR/LINK pointing at TARGET (a
# file outside the output folder that does not exist), then runs check.cmake (which gets
# the same -D definitions; pass NO_FILE=TARGET to check that nothing was written there).
file(REMOVE_RECURSE "${OUT_DIR}")
file(MAKE_DIRECTORY "${OUT_DIR}")
file(REMOVE "${TARGET}")
file(CREATE_LINK "${TARGET}" "${OUT_DIR}/${LINK}" SYMBOLIC)
include(${CMAKE_CURRENT_LIST_DIR}/../check.cmake)
