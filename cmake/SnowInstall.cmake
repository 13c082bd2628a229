# cmake --install exports snowConfig.cmake so `find_package(snow)` gives
# snow::sim and, when built, snow::scene, snow::render and snow::c (snow::ecs
# and snow::files, the renderer's file writer, come along as their
# dependencies). The public API is include/snow/ alone:
#   <snow/snow.hpp>    snow::sim     the Simulation (no GL), with defs.hpp,
#                                    views.hpp, error.hpp, task_system.hpp, allocator.hpp
#   <snow/scene.hpp>   snow::scene   glTF scene loading (no GL)
#   <snow/render.hpp>  snow::render  the renderer and its GL contexts
#   <snow/snow.h>      snow::c       the C API
# No installed header includes an internal one (ecs/, systems/, render/,
# game/): configuring fails if one does, and snow_header_check compiles each
# alone with only GLM on the include path.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

# The headers each public header reaches, listed so a new include is a
# visible change here; snow_check_header_closure() fails the configure step
# when an include was added or dropped without updating these lists.
set(SNOW_SIM_HEADERS
    include/snow/snow.hpp include/snow/defs.hpp include/snow/error.hpp
    include/snow/task_system.hpp include/snow/views.hpp include/snow/allocator.hpp)
set(SNOW_SCENE_HEADERS include/snow/scene.hpp include/snow/render.hpp)
set(SNOW_RENDER_HEADERS include/snow/render.hpp)
set(SNOW_INTERNAL "^(ecs|systems|render|game)/")

# Every header reachable from `root` through #include "dir/file.hpp" (paths
# from the source root) and #include <snow/file.hpp>.
function(snow_header_closure root out)
    set(todo ${root})
    set(seen)
    while(todo)
        list(POP_FRONT todo header)
        if(header IN_LIST seen)
            continue()
        endif()
        list(APPEND seen ${header})
        set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS
                     ${PROJECT_SOURCE_DIR}/${header})
        file(STRINGS ${PROJECT_SOURCE_DIR}/${header} lines REGEX "^#include [\"<]")
        foreach(line ${lines})
            if(line MATCHES "^#include \"([^\"]+)\"")
                list(APPEND todo ${CMAKE_MATCH_1})
            elseif(line MATCHES "^#include <(snow/[^>]+)>")
                list(APPEND todo include/${CMAKE_MATCH_1})
            endif()
        endforeach()
    endwhile()
    set(${out} ${seen} PARENT_SCOPE)
endfunction()

# Fails when the headers `root` reaches differ from the list `listed`, or
# when `forbidden` (a regex) matches one of them.
function(snow_check_header_closure root listed forbidden)
    snow_header_closure(${root} reached)
    set(missing ${reached})
    list(REMOVE_ITEM missing ${${listed}})
    set(stale ${${listed}})
    list(REMOVE_ITEM stale ${reached})
    if(missing OR stale)
        message(FATAL_ERROR "cmake/SnowInstall.cmake: ${listed} is out of date for ${root}: "
                            "add [${missing}], remove [${stale}]")
    endif()
    foreach(header ${reached})
        if(forbidden AND header MATCHES "${forbidden}")
            message(FATAL_ERROR "${root} reaches ${header}: a public header must not "
                                "include an internal one")
        endif()
    endforeach()
endfunction()

# Exports `target` (when built) with its public header `root`, which reaches
# snow::sim's headers and those listed in `listed`, and never `forbidden`.
set(SNOW_EXPORTED snow_ecs snow_files)
set(SNOW_INSTALLED_HEADERS)
function(snow_public_target target root listed forbidden)
    if(NOT TARGET ${target})
        return()
    endif()
    # Not named `reached`: snow_check_header_closure computes its own
    # `reached`, which would shadow this list and make the check vacuous.
    set(public_headers ${SNOW_SIM_HEADERS} ${${listed}})
    list(REMOVE_DUPLICATES public_headers)
    snow_check_header_closure(${root} public_headers "${forbidden}")
    set(SNOW_EXPORTED ${SNOW_EXPORTED} ${target} PARENT_SCOPE)
    set(SNOW_INSTALLED_HEADERS ${SNOW_INSTALLED_HEADERS} ${public_headers} PARENT_SCOPE)
endfunction()
snow_public_target(snow_sim include/snow/snow.hpp SNOW_SIM_HEADERS "${SNOW_INTERNAL}")
snow_public_target(snow_scene include/snow/scene.hpp SNOW_SCENE_HEADERS "${SNOW_INTERNAL}")
snow_public_target(snow_render include/snow/render.hpp SNOW_RENDER_HEADERS "${SNOW_INTERNAL}")
# The C API reaches no header but its own (and the C library's).
if(TARGET snow_c)
    set(SNOW_C_HEADERS include/snow/snow.h)
    snow_check_header_closure(include/snow/snow.h SNOW_C_HEADERS "${SNOW_INTERNAL}")
    list(APPEND SNOW_EXPORTED snow_c)
    list(APPEND SNOW_INSTALLED_HEADERS ${SNOW_C_HEADERS})
endif()
list(REMOVE_DUPLICATES SNOW_INSTALLED_HEADERS)

foreach(t ${SNOW_EXPORTED})
    string(REPLACE "snow_" "" export_name ${t})
    set_target_properties(${t} PROPERTIES EXPORT_NAME ${export_name})
endforeach()

install(TARGETS ${SNOW_EXPORTED} EXPORT snowTargets
    ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
    LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
install(FILES ${SNOW_INSTALLED_HEADERS} DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/snow)

install(EXPORT snowTargets NAMESPACE snow:: DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/snow)
configure_package_config_file(cmake/snowConfig.cmake.in
    ${PROJECT_BINARY_DIR}/snowConfig.cmake
    INSTALL_DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/snow)
write_basic_package_version_file(${PROJECT_BINARY_DIR}/snowConfigVersion.cmake
    COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/snowConfig.cmake ${PROJECT_BINARY_DIR}/snowConfigVersion.cmake
    DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/snow)

# Every installed header compiles alone, as the first include of a
# consumer's file (<snow/snow.h> as C11): one generated source per header,
# built with the project's warnings as part of the tests' build.
if(SNOW_BUILD_TESTS)
    set(header_checks)
    foreach(header ${SNOW_INSTALLED_HEADERS})
        string(MAKE_C_IDENTIFIER ${header} name)
        set(ext cpp)
        if(header MATCHES "\\.h$")
            set(ext c)
        endif()
        string(REGEX REPLACE "^include/" "" included ${header})
        set(check ${PROJECT_BINARY_DIR}/header_check/${name}.${ext})
        file(CONFIGURE OUTPUT ${check} CONTENT "#include \"${included}\"\n")
        list(APPEND header_checks ${check})
    endforeach()
    add_library(snow_header_check OBJECT ${header_checks})
    set_target_properties(snow_header_check PROPERTIES C_STANDARD 11 C_STANDARD_REQUIRED ON)
    target_include_directories(snow_header_check PRIVATE ${PROJECT_SOURCE_DIR}/include)
    target_link_libraries(snow_header_check PRIVATE glm::glm)
    snow_set_options(snow_header_check)
    snow_require_sized_deallocation(snow_header_check)
endif()
