# ws_public_headers(OUT ROOT_DIR HEADER...): the headers under ROOT_DIR that
# the HEADERs (paths relative to ROOT_DIR) include with #include "...",
# directly or through one another, the HEADERs themselves among them;
# relative to ROOT_DIR.
# The install puts exactly these beside the umbrella header, so a header the
# public interface starts to include is installed with it. Configure runs
# again when any of them changes.
function(ws_public_headers out root)
  set(found "")
  set(pending ${ARGN})
  while(pending)
    list(POP_FRONT pending current)
    if(current IN_LIST found OR NOT EXISTS ${root}/${current})
      continue()  # done already, or not ours (the generated LCM types are installed whole)
    endif()
    list(APPEND found ${current})
    file(STRINGS ${root}/${current} includes REGEX "^[ \t]*#[ \t]*include[ \t]*\"")
    foreach(line ${includes})
      string(REGEX REPLACE "^[ \t]*#[ \t]*include[ \t]*\"([^\"]+)\".*" "\\1" included "${line}")
      list(APPEND pending ${included})
    endforeach()
  endwhile()
  list(TRANSFORM found PREPEND ${root}/ OUTPUT_VARIABLE paths)
  set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${paths})
  set(${out} ${found} PARENT_SCOPE)
endfunction()
