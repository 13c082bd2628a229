# cmake --install exports snowConfig.cmake so `find_package(snow)` gives
# snow::ecs, snow::sim and, when built, snow::render and snow::scene.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(SNOW_EXPORTED snow_ecs snow_sim)
set(SNOW_HEADER_DIRS ecs systems)
foreach(t snow_render snow_scene)
    if(TARGET ${t})
        list(APPEND SNOW_EXPORTED ${t})
    endif()
endforeach()

foreach(t ${SNOW_EXPORTED})
    string(REPLACE "snow_" "" export_name ${t})
    set_target_properties(${t} PROPERTIES EXPORT_NAME ${export_name})
endforeach()

install(TARGETS ${SNOW_EXPORTED} EXPORT snowTargets
    ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
    LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
    INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/snow)
foreach(dir ${SNOW_HEADER_DIRS})
    install(DIRECTORY ${dir}/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/snow/${dir}
            FILES_MATCHING PATTERN "*.hpp")
endforeach()
# snow::render's public headers; the pass internals include glad and stay private.
if(TARGET snow_render)
    install(FILES render/camera.hpp render/frame_timings.hpp render/gl_context.hpp
                  render/image.hpp render/render_error.hpp render/render_pass.hpp
                  render/render_settings.hpp render/renderer.hpp render/shader.hpp
                  render/osmesa_context.hpp render/glfw_context.hpp
            DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/snow/render)
endif()
# snow::scene's one public header (the scene_*.hpp beside it are internals).
if(TARGET snow_scene)
    install(FILES game/scene/scene_loader.hpp DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/snow/game/scene)
endif()
# The public facade: #include <snow/snow.hpp>
install(FILES systems/snow.hpp DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/snow)

install(EXPORT snowTargets NAMESPACE snow:: DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/snow)
configure_package_config_file(cmake/snowConfig.cmake.in
    ${PROJECT_BINARY_DIR}/snowConfig.cmake
    INSTALL_DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/snow)
write_basic_package_version_file(${PROJECT_BINARY_DIR}/snowConfigVersion.cmake
    COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/snowConfig.cmake ${PROJECT_BINARY_DIR}/snowConfigVersion.cmake
    DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/snow)
