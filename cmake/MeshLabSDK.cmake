# The MeshLab 2020.09 plugin SDK: headers from Debian's own source package of the installed
# meshlab (fetched once into a cache by fetch-meshlab-sdk.sh), and Debian's libmeshlab-common.so.
#
# Provides the imported target MeshLab::common and the function voxelfair_add_meshlab_plugin().

set(MESHLAB_SDK_CACHE "$ENV{HOME}/.cache/voxelfair" CACHE PATH "Where the MeshLab source package is unpacked")
set(MESHLAB_SDK_DIR "" CACHE PATH "An unpacked MeshLab 2020.09 source tree (fetched into MESHLAB_SDK_CACHE when empty)")
set(MESHLAB_LIBRARY_DIR "/usr/lib/x86_64-linux-gnu/meshlab" CACHE PATH "Folder of Debian's libmeshlab-common.so and plugins/")

if(NOT MESHLAB_SDK_DIR OR NOT EXISTS "${MESHLAB_SDK_DIR}/src/common/interfaces.h")
  execute_process(
    COMMAND bash "${CMAKE_CURRENT_LIST_DIR}/fetch-meshlab-sdk.sh" "${MESHLAB_SDK_CACHE}"
    OUTPUT_VARIABLE _sdk_out RESULT_VARIABLE _sdk_rc OUTPUT_STRIP_TRAILING_WHITESPACE)
  if(NOT _sdk_rc EQUAL 0)
    message(FATAL_ERROR "Could not fetch the MeshLab SDK (see above). Install the packages with "
                        "'bash voxelfair.sh setup', or configure with -DVOXELFAIR_BUILD_PLUGINS=OFF.")
  endif()
  string(REGEX REPLACE ".*\n" "" _sdk_out "${_sdk_out}")
  set(MESHLAB_SDK_DIR "${_sdk_out}" CACHE PATH "An unpacked MeshLab 2020.09 source tree" FORCE)
endif()
message(STATUS "MeshLab SDK: ${MESHLAB_SDK_DIR}")

find_library(MESHLAB_COMMON_LIBRARY meshlab-common PATHS "${MESHLAB_LIBRARY_DIR}" NO_DEFAULT_PATH REQUIRED)
find_package(Qt5 REQUIRED COMPONENTS Core Gui Widgets OpenGL Xml)
find_package(GLEW REQUIRED)
find_package(OpenGL REQUIRED)
find_package(Eigen3 REQUIRED NO_MODULE)

add_library(MeshLab::common SHARED IMPORTED GLOBAL)
set_target_properties(MeshLab::common PROPERTIES IMPORTED_LOCATION "${MESHLAB_COMMON_LIBRARY}")
# SYSTEM: MeshLab's and vcglib's own warnings are not ours to fix.
target_include_directories(MeshLab::common SYSTEM INTERFACE
  "${MESHLAB_SDK_DIR}/src" "${MESHLAB_SDK_DIR}/src/common" "${MESHLAB_SDK_DIR}/vcglib")
# float must match Debian's build, or CMeshO's layout differs from the library's.
target_compile_definitions(MeshLab::common INTERFACE MESHLAB_SCALAR=float)
target_link_libraries(MeshLab::common INTERFACE
  Qt5::Core Qt5::Gui Qt5::Widgets Qt5::OpenGL Qt5::Xml GLEW::GLEW OpenGL::GL Eigen3::Eigen)

set(MESHLAB_PLUGIN_INSTALL_DIR "${MESHLAB_LIBRARY_DIR}/plugins" CACHE PATH "Where cmake --install puts the plugins")

# voxelfair_add_meshlab_plugin(name sources...): a Qt MODULE loaded by MeshLab's plugin manager.
function(voxelfair_add_meshlab_plugin name)
  add_library(${name} MODULE ${ARGN})
  set_target_properties(${name} PROPERTIES AUTOMOC ON PREFIX "lib"
    LIBRARY_OUTPUT_DIRECTORY "${CMAKE_BINARY_DIR}/plugins")
  target_link_libraries(${name} PRIVATE MeshLab::common)
  # Debian built MeshLab with asserts on: keep vcglib's asserts in our adapter code too, so a
  # misuse asserts here as it would in MeshLab instead of corrupting memory.
  target_compile_options(${name} PRIVATE -UNDEBUG -Wno-deprecated-copy -Wno-ignored-qualifiers)
  target_link_options(${name} PRIVATE -Wl,--no-undefined)
  install(TARGETS ${name} LIBRARY DESTINATION "${MESHLAB_PLUGIN_INSTALL_DIR}")
endfunction()

# vcglib's headers alone (no Qt, no MeshLab): lets tests and benchmarks run vcglib's own
# algorithms, e.g. Taubin smoothing, in the same process as ours for side-by-side figures.
add_library(vcglib_headers INTERFACE)
target_include_directories(vcglib_headers SYSTEM INTERFACE "${MESHLAB_SDK_DIR}/vcglib")
target_link_libraries(vcglib_headers INTERFACE Eigen3::Eigen)
add_library(vcglib::headers ALIAS vcglib_headers)
