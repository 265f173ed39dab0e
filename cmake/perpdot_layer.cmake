# perpdot's layers as library targets, each compiled against a *view* of the tree: a directory in
# the build tree holding symlinks to the layer's own headers and to those of the layers below it,
# never to a layer above. An `#include "perpdot/scene.hpp"` or `"scene/..."` in src/core therefore
# fails to compile ("No such file or directory") instead of quietly tying the engine to its tools.
#
#   perpdot_layer(<layer> OUTPUT_NAME <library file name> FOLDERS <src/ folders>
#                 PUBLIC_HEADERS <file names in include/perpdot/> [BELOW <lower layers>])
#
# defines the library perpdot_<layer> (alias perpdot::<layer>, exported as perpdot::<layer>) from
# every src/<folder>/*.cpp -- a file added to a folder joins its layer at the next build.
#   <view>/include/perpdot/<header>  the layer's public headers (PUBLIC: what its users see)
#   <view>/src/<folder>              src/<folder> of this layer and every layer below (PRIVATE)
function(perpdot_layer layer)
  cmake_parse_arguments(arg "" "OUTPUT_NAME" "FOLDERS;PUBLIC_HEADERS;BELOW" ${ARGN})
  set(view ${PROJECT_BINARY_DIR}/layers/${layer})
  file(REMOVE_RECURSE ${view})  # a header may have changed layer since the last configure
  file(MAKE_DIRECTORY ${view}/include/perpdot ${view}/src)
  foreach(header IN LISTS arg_PUBLIC_HEADERS)
    file(CREATE_LINK ${PROJECT_SOURCE_DIR}/include/perpdot/${header} ${view}/include/perpdot/${header} SYMBOLIC)
  endforeach()

  set(sources)
  set(visibleFolders ${arg_FOLDERS})
  foreach(below IN LISTS arg_BELOW)
    get_property(belowFolders GLOBAL PROPERTY perpdot_layer_folders_${below})
    list(APPEND visibleFolders ${belowFolders})
  endforeach()
  set_property(GLOBAL PROPERTY perpdot_layer_folders_${layer} ${visibleFolders})
  foreach(folder IN LISTS visibleFolders)
    file(CREATE_LINK ${PROJECT_SOURCE_DIR}/src/${folder} ${view}/src/${folder} SYMBOLIC)
  endforeach()
  foreach(folder IN LISTS arg_FOLDERS)
    file(GLOB folderSources CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/src/${folder}/*.cpp)
    list(APPEND sources ${folderSources})
  endforeach()

  set(target perpdot_${layer})
  add_library(${target} ${sources})
  add_library(perpdot::${layer} ALIAS ${target})
  # SOVERSION major.minor: before 1.0 every minor version may change the ABI (and the package
  # version file accepts the same minor version only).
  set_target_properties(${target} PROPERTIES OUTPUT_NAME ${arg_OUTPUT_NAME} EXPORT_NAME ${layer}
    VERSION ${PROJECT_VERSION} SOVERSION ${PROJECT_VERSION_MAJOR}.${PROJECT_VERSION_MINOR})
  target_include_directories(${target}
    PUBLIC $<BUILD_INTERFACE:${view}/include> $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>
    PRIVATE ${view}/src)
  list(TRANSFORM arg_BELOW PREPEND perpdot_ OUTPUT_VARIABLE belowTargets)
  # perpdot_options (warnings, -ffp-contract=off, sanitizers) only while building perpdot itself:
  # a game that links perpdot does not inherit its warning flags.
  target_link_libraries(${target} PUBLIC ${belowTargets} PRIVATE $<BUILD_INTERFACE:perpdot_options>)
  target_compile_features(${target} PUBLIC cxx_std_20)
endfunction()

# perpdot_pkg_config(<layer> <description> <Requires> <private Requires>) writes
# <binary dir>/pkgconfig/<library file name>.pc for the install step. Its prefix is found from the
# .pc file's own place (${pcfiledir}), so `cmake --install --prefix ANY` gives a working file.
# A static library's private dependencies must be linked by its users: then they are Requires.
function(perpdot_pkg_config layer description requires requiresPrivate)
  get_target_property(PC_LIB perpdot_${layer} OUTPUT_NAME)
  set(PC_DESCRIPTION "${description}")
  file(RELATIVE_PATH PC_PREFIX_FROM_PCFILEDIR ${CMAKE_INSTALL_FULL_LIBDIR}/pkgconfig ${CMAKE_INSTALL_PREFIX})
  if(BUILD_SHARED_LIBS)
    set(PC_REQUIRES "${requires}")
    set(PC_REQUIRES_PRIVATE "${requiresPrivate}")
  else()
    string(JOIN " " PC_REQUIRES ${requires} ${requiresPrivate})
    set(PC_REQUIRES_PRIVATE "")
  endif()
  configure_file(${PROJECT_SOURCE_DIR}/cmake/perpdot.pc.in ${PROJECT_BINARY_DIR}/pkgconfig/${PC_LIB}.pc @ONLY)
endfunction()
