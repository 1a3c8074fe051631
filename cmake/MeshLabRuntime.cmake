# A private MeshLab runtime in the build tree: copies of Debian's meshlabserver and meshlab
# binaries in runtime/bin, so MeshLab looks for plugins in runtime/lib/x86_64-linux-gnu/meshlab/plugins
# (the parent of the binary's real folder + lib/...), where the system plugins and ours are linked.
# Tests and scripts use it; nothing is installed. `cmake --install` serves the system-wide GUI.

set(VOXELFAIR_RUNTIME_DIR "${CMAKE_BINARY_DIR}/runtime")
set(_stage_script "${CMAKE_CURRENT_LIST_DIR}/stage-runtime.sh")
add_custom_target(runtime ALL
  COMMAND bash "${_stage_script}" "${VOXELFAIR_RUNTIME_DIR}" "${MESHLAB_LIBRARY_DIR}"
          "$<TARGET_FILE:io_vxl>" "$<TARGET_FILE:io_gltf>" "$<TARGET_FILE:filter_voxelfair>"
  DEPENDS io_vxl io_gltf filter_voxelfair "${_stage_script}"
  COMMENT "Staging the private MeshLab runtime in ${VOXELFAIR_RUNTIME_DIR}"
  VERBATIM)
