# granairCG: the CG-fields command (coupling/cg/app). Included by
# coupling/CMakeLists.txt after the library target exists.
add_executable(granairCG ${CMAKE_CURRENT_LIST_DIR}/app/granairCG.cpp)
target_link_libraries(granairCG PRIVATE granair_coupling)
target_compile_options(granairCG PRIVATE ${GRANAIR_WARNINGS})
