# find_package(svgmotion) for plugin authors: provides svgmotion::plugin_sdk (the C header
# svgmotion/plugin.h), SVGMOTION_PLUGIN_ABI and SVGMOTION_PLUGIN_DIR (where installed plugins
# live). A plugin is a MODULE library named svgm_<stage>_<name> exporting svgm_plugin_entry().
get_filename_component(_svgm_prefix "${CMAKE_CURRENT_LIST_DIR}/../../.." ABSOLUTE)
if(NOT TARGET svgmotion::plugin_sdk)
  add_library(svgmotion::plugin_sdk INTERFACE IMPORTED)
  set_target_properties(svgmotion::plugin_sdk PROPERTIES
    INTERFACE_INCLUDE_DIRECTORIES "${_svgm_prefix}/include")
endif()
set(SVGMOTION_PLUGIN_ABI 1)
set(SVGMOTION_PLUGIN_DIR "${_svgm_prefix}/lib/svgmotion/plugins")
unset(_svgm_prefix)
