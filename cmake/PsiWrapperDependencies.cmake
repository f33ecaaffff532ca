# psi_wrappers_depend_on_setting_list(<wrapper source>...): each generated wrapper source is made
# again when Core/PsiSettingList.h changes. The setters of the mapper and the representation come
# from that list's macros, which VTK's wrappers expand, but VTK's wrapping commands depend only on
# the wrapped header itself. Call it in the folder whose wrapping made the sources; a name that
# VTK's wrappers did not make there is reported, since the dependency would then be missing.
function (psi_wrappers_depend_on_setting_list)
  foreach (output IN LISTS ARGN)
    get_source_file_property(generated "${output}" GENERATED)
    if (generated)
      add_custom_command(OUTPUT "${output}" APPEND
        DEPENDS "${PROJECT_SOURCE_DIR}/Core/PsiSettingList.h")
    else ()
      message(AUTHOR_WARNING "No wrapping command makes ${output}: it will not be made again "
        "when Core/PsiSettingList.h changes.")
    endif ()
  endforeach ()
endfunction ()
