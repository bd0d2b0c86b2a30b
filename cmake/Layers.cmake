# Reads the layer table (cmake/layers.txt): FLOODLIGHT_LAYERS lists the libraries bottom to top;
# for each NAME, FLOODLIGHT_LAYER_<NAME>_KIND is cpu or gl and FLOODLIGHT_LAYER_<NAME>_PUBLIC /
# _PRIVATE its direct internal links. floodlight_link_layer(NAME) links floodlight_NAME from the
# table; floodlight_check_layers() stops the configure when a library links an internal library
# the table does not name (say, added by hand in its own CMakeLists.txt).

set(FLOODLIGHT_LAYERS_FILE "${CMAKE_CURRENT_LIST_DIR}/layers.txt")
set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS "${FLOODLIGHT_LAYERS_FILE}")

set(FLOODLIGHT_LAYERS "")
file(STRINGS "${FLOODLIGHT_LAYERS_FILE}" _layer_lines)
foreach(_line IN LISTS _layer_lines)
  if(_line MATCHES "^[ \t]*(#|$)")
    continue()
  endif()
  if(NOT _line MATCHES "^([a-z_]+)[ \t]+(cpu|gl):(.*)$")
    message(FATAL_ERROR "${FLOODLIGHT_LAYERS_FILE}: not 'library kind: links': ${_line}")
  endif()
  set(_name ${CMAKE_MATCH_1})
  set(_kind ${CMAKE_MATCH_2})
  string(REGEX REPLACE "[ \t]+" ";" _links "${CMAKE_MATCH_3}")
  set(_public "")
  set(_private "")
  foreach(_link IN LISTS _links)
    if(_link STREQUAL "")
      continue()
    endif()
    set(_scope _public)
    if(_link MATCHES "^\\[([a-z_]+)\\]$")
      set(_link ${CMAKE_MATCH_1})
      set(_scope _private)
    endif()
    # Bottom to top: a link to a later line (or an unknown name) would be a cycle or a typo.
    if(NOT _link IN_LIST FLOODLIGHT_LAYERS)
      message(FATAL_ERROR "${FLOODLIGHT_LAYERS_FILE}: ${_name} links '${_link}', "
                          "which is not a library on a line above it")
    endif()
    if(_kind STREQUAL "cpu" AND NOT FLOODLIGHT_LAYER_${_link}_KIND STREQUAL "cpu")
      message(FATAL_ERROR "${FLOODLIGHT_LAYERS_FILE}: the cpu library ${_name} links the gl "
                          "library ${_link}")
    endif()
    list(APPEND ${_scope} ${_link})
  endforeach()
  list(APPEND FLOODLIGHT_LAYERS ${_name})
  set(FLOODLIGHT_LAYER_${_name}_KIND ${_kind})
  set(FLOODLIGHT_LAYER_${_name}_PUBLIC ${_public})
  set(FLOODLIGHT_LAYER_${_name}_PRIVATE ${_private})
endforeach()

# The table's links of floodlight_NAME (called from the top level after add_subdirectory(NAME)).
function(floodlight_link_layer name)
  list(TRANSFORM FLOODLIGHT_LAYER_${name}_PUBLIC PREPEND floodlight_ OUTPUT_VARIABLE public)
  list(TRANSFORM FLOODLIGHT_LAYER_${name}_PRIVATE PREPEND floodlight_ OUTPUT_VARIABLE private)
  target_link_libraries(floodlight_${name} PUBLIC ${public} PRIVATE ${private})
endfunction()

# Every internal library that a built library links must be one its line names, in the scope it
# names. LINK_LIBRARIES holds both scopes; INTERFACE_LINK_LIBRARIES the PUBLIC ones (and the
# PRIVATE ones of a static library as $<LINK_ONLY:...>).
function(floodlight_check_layers)
  foreach(name IN LISTS FLOODLIGHT_LAYERS)
    if(NOT TARGET floodlight_${name})
      continue()
    endif()
    set(allowed ${FLOODLIGHT_LAYER_${name}_PUBLIC} ${FLOODLIGHT_LAYER_${name}_PRIVATE})
    get_target_property(links floodlight_${name} LINK_LIBRARIES)
    get_target_property(interface floodlight_${name} INTERFACE_LINK_LIBRARIES)
    foreach(scope links interface)
      foreach(link IN LISTS ${scope})
        string(REGEX REPLACE "^\\$<LINK_ONLY:(.*)>$" "\\1" bare "${link}")
        if(NOT bare MATCHES "^floodlight_(.*)$" OR NOT CMAKE_MATCH_1 IN_LIST FLOODLIGHT_LAYERS)
          continue()
        endif()
        set(used ${CMAKE_MATCH_1})
        if(NOT used IN_LIST allowed)
          message(FATAL_ERROR "floodlight_${name} links floodlight_${used}, which its line in "
                              "${FLOODLIGHT_LAYERS_FILE} does not name")
        endif()
        if(scope STREQUAL "interface" AND bare STREQUAL link
           AND NOT used IN_LIST FLOODLIGHT_LAYER_${name}_PUBLIC)
          message(FATAL_ERROR "floodlight_${name} links floodlight_${used} PUBLIC; "
                              "${FLOODLIGHT_LAYERS_FILE} has it PRIVATE ([${used}])")
        endif()
      endforeach()
    endforeach()
  endforeach()
endfunction()
