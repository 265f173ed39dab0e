# perpdot's layers as library targets, each compiled against a *view* of the tree: a directory in
# the build tree holding symlinks to the layer's own headers and to what the layers below it
# export, never to a layer above. An `#include "perpdot/scene.hpp"` or `"scene/..."` in src/core
# therefore fails to compile ("No such file or directory") instead of quietly tying the engine to
# its tools.
#
#   perpdot_layer(<layer> [OBJECT] [OUTPUT_NAME <library file name>] FOLDERS <src/ folders>
#                 PUBLIC_HEADERS <file names in include/perpdot/> [EXPORTS <paths under src/>]
#                 [SEES <paths under src/>] [PARTS <object layers>] [BELOW <lower layers>])
#
# defines perpdot_<layer> from every .cpp under src/<folder> (recursively, but for folders named
# avx2, whose files are compiled with their own flags, and for the folders of its PARTS) -- a file
# added to a folder joins its layer at the next build. A library layer is perpdot::<layer>
# (exported as such); an OBJECT layer is compiled apart, behind its own fence, and its objects
# become part of the library layer that names it in PARTS, which sees all of its folders. A part
# may be a folder of the library's own (core/solver in core).
#   <view>/include/perpdot/<header>  the layer's public headers (PUBLIC: what its users see)
#   <view>/src/<folder>              the layer's own folders and its PARTS' (PRIVATE)
#   <view>/src/<path>                what each layer in BELOW exports (EXPORTS: files or folders),
#                                    and the files or folders named in SEES: for a part, the few
#                                    headers of the library around it that it reads
function(perpdot_layer layer)
  cmake_parse_arguments(arg "OBJECT" "OUTPUT_NAME" "FOLDERS;PUBLIC_HEADERS;EXPORTS;SEES;PARTS;BELOW" ${ARGN})
  set(view ${PROJECT_BINARY_DIR}/layers/${layer})
  file(REMOVE_RECURSE ${view})  # a header may have changed layer since the last configure
  file(MAKE_DIRECTORY ${view}/include/perpdot ${view}/src)
  foreach(header IN LISTS arg_PUBLIC_HEADERS)
    file(CREATE_LINK ${PROJECT_SOURCE_DIR}/include/perpdot/${header} ${view}/include/perpdot/${header} SYMBOLIC)
  endforeach()

  set(visible ${arg_FOLDERS} ${arg_SEES})
  set(partFolders)
  foreach(part IN LISTS arg_PARTS)
    get_property(folders GLOBAL PROPERTY perpdot_layer_folders_${part})
    list(APPEND partFolders ${folders})
  endforeach()
  list(APPEND visible ${partFolders})
  set_property(GLOBAL PROPERTY perpdot_layer_folders_${layer} ${arg_FOLDERS})
  set_property(GLOBAL PROPERTY perpdot_layer_exports_${layer} ${arg_EXPORTS})
  foreach(below IN LISTS arg_BELOW)
    get_property(belowExports GLOBAL PROPERTY perpdot_layer_exports_${below})
    list(APPEND visible ${belowExports})
  endforeach()
  set(linked)
  foreach(path IN LISTS visible)
    # A path inside one already linked (a part's folder inside the library's) is there already.
    set(inside FALSE)
    foreach(other IN LISTS linked)
      string(FIND "${path}/" "${other}/" at)
      if(at EQUAL 0)
        set(inside TRUE)
      endif()
    endforeach()
    if(inside)
      continue()
    endif()
    list(APPEND linked ${path})
    get_filename_component(parent ${view}/src/${path} DIRECTORY)
    file(MAKE_DIRECTORY ${parent})
    file(CREATE_LINK ${PROJECT_SOURCE_DIR}/src/${path} ${view}/src/${path} SYMBOLIC)
  endforeach()

  set(sources)
  foreach(folder IN LISTS arg_FOLDERS)
    file(GLOB_RECURSE folderSources CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/src/${folder}/*.cpp)
    list(FILTER folderSources EXCLUDE REGEX "/avx2/")
    list(APPEND sources ${folderSources})
  endforeach()
  foreach(folder IN LISTS partFolders)  # compiled by the part
    file(GLOB_RECURSE partSources CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/src/${folder}/*.cpp)
    if(partSources)
      list(REMOVE_ITEM sources ${partSources})
    endif()
  endforeach()

  set(target perpdot_${layer})
  # perpdot_options (warnings, -ffp-contract=off, sanitizers) only while building perpdot itself:
  # a game that links perpdot does not inherit its warning flags.
  if(arg_OBJECT)
    add_library(${target} OBJECT ${sources})
    if(BUILD_SHARED_LIBS)
      set_target_properties(${target} PROPERTIES POSITION_INDEPENDENT_CODE ON)
    endif()
    target_include_directories(${target} PRIVATE ${view}/include ${view}/src)
    target_link_libraries(${target} PRIVATE perpdot_options)
    target_compile_features(${target} PRIVATE cxx_std_20)
    return()
  endif()
  add_library(${target} ${sources})
  add_library(perpdot::${layer} ALIAS ${target})
  foreach(part IN LISTS arg_PARTS)
    target_sources(${target} PRIVATE $<TARGET_OBJECTS:perpdot_${part}>)
  endforeach()
  # SOVERSION major.minor: before 1.0 every minor version may change the ABI (and the package
  # version file accepts the same minor version only).
  set_target_properties(${target} PROPERTIES OUTPUT_NAME ${arg_OUTPUT_NAME} EXPORT_NAME ${layer}
    VERSION ${PROJECT_VERSION} SOVERSION ${PROJECT_VERSION_MAJOR}.${PROJECT_VERSION_MINOR})
  target_include_directories(${target}
    PUBLIC $<BUILD_INTERFACE:${view}/include> $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>
    PRIVATE ${view}/src)
  set(belowLibraries)
  foreach(below IN LISTS arg_BELOW)
    if(NOT TARGET perpdot_${below})
      message(FATAL_ERROR "perpdot_layer(${layer}): no layer ${below} below it")
    endif()
    get_target_property(belowType perpdot_${below} TYPE)
    if(NOT belowType STREQUAL "OBJECT_LIBRARY")  # an object layer's code comes with the library of its PARTS
      list(APPEND belowLibraries perpdot_${below})
    endif()
  endforeach()
  target_link_libraries(${target} PUBLIC ${belowLibraries} PRIVATE $<BUILD_INTERFACE:perpdot_options>)
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
