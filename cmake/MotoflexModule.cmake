# motoflex_module(<name> SOURCES ... [DEPENDS <modules>...] [PUBLIC_LIBS ...] [PRIVATE_LIBS ...])
#
# One static library per module of cmake/module_layers.txt: target motoflex_<name>, alias
# motoflex::<name>, public headers under include/motoflex/<module>/. DEPENDS names other
# motoflex modules; configuring fails when one of them is not on a lower layer, so an upward
# link cannot be written. The targets are installed and exported as motoflex::<name>.

file(STRINGS ${CMAKE_CURRENT_LIST_DIR}/module_layers.txt _motoflex_layer_lines REGEX "^[0-9]")
foreach(_line IN LISTS _motoflex_layer_lines)
  string(REGEX MATCH "^([0-9]+)[ \t]+([a-z0-9_]+)" _ "${_line}")
  set(MOTOFLEX_LAYER_${CMAKE_MATCH_2} ${CMAKE_MATCH_1})
endforeach()

function(motoflex_module name)
  cmake_parse_arguments(M "" "" "SOURCES;DEPENDS;PUBLIC_LIBS;PRIVATE_LIBS" ${ARGN})
  if(NOT DEFINED MOTOFLEX_LAYER_${name})
    message(FATAL_ERROR "module '${name}' is not listed in cmake/module_layers.txt")
  endif()
  set(deps)
  foreach(dep IN LISTS M_DEPENDS)
    if(NOT DEFINED MOTOFLEX_LAYER_${dep})
      message(FATAL_ERROR "module '${name}' depends on unknown module '${dep}'")
    endif()
    if(NOT MOTOFLEX_LAYER_${dep} LESS MOTOFLEX_LAYER_${name})
      message(FATAL_ERROR "module '${name}' (layer ${MOTOFLEX_LAYER_${name}}) may not use "
                          "'${dep}' (layer ${MOTOFLEX_LAYER_${dep}}): only lower layers")
    endif()
    list(APPEND deps motoflex_${dep})
  endforeach()
  add_library(motoflex_${name} STATIC ${M_SOURCES})
  add_library(motoflex::${name} ALIAS motoflex_${name})
  target_include_directories(motoflex_${name} PUBLIC
    $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}/include>
    $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
  target_link_libraries(motoflex_${name} PUBLIC ${deps} ${M_PUBLIC_LIBS} PRIVATE ${M_PRIVATE_LIBS})
  target_compile_options(motoflex_${name} PRIVATE ${MOTOFLEX_WARNINGS})
  # Position-independent code only when a shared object (the Python module) links the modules.
  set_target_properties(motoflex_${name} PROPERTIES EXPORT_NAME ${name}
                        POSITION_INDEPENDENT_CODE ${MOTOFLEX_PIC})
  install(TARGETS motoflex_${name} EXPORT motoflexTargets
          ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
  set_property(GLOBAL APPEND PROPERTY MOTOFLEX_MODULES ${name})
endfunction()
