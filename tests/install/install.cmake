# Version and installation tests, included from the end of CMakeLists.txt (label unit).
# frix_version: `frix --version` exits 0 and its first line is "frix <project VERSION>".
# install_tree: `cmake --install` of this build into a scratch prefix P, then P/bin/frix
# --version, every P/bin/frix-<script> --help and the documentation in P/share/doc/frix.
add_test(NAME frix_version
         COMMAND bash ${PROJECT_SOURCE_DIR}/tests/install/check_version.sh
                 $<TARGET_FILE:frix> ${PROJECT_VERSION})
add_test(NAME install_tree
         COMMAND bash ${PROJECT_SOURCE_DIR}/tests/install/check_install.sh
                 ${CMAKE_COMMAND} ${PROJECT_BINARY_DIR} ${PROJECT_VERSION})
set_tests_properties(frix_version install_tree PROPERTIES LABELS unit)
