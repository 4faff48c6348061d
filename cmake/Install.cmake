# install(): the static libraries, their public headers and the CMake package that finds them
# (cmake/shadowfxConfig.cmake.in), plus the shadowfx tool, the compile worker and the runtime modules.
#
# Headers install under include/shadowfx/ (include/shadowfx/fx/..., include/shadowfx/runtime/...), which is
# the installed targets' include directory: an application spells them as this source tree does
# (<fx/EffectParser.h>, <runtime/EffectRenderer.h>), and the short names fx/ and runtime/ do not land
# directly in a shared prefix such as /usr/local/include. include/private/ is never installed.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)
set(SHADOWFX_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/shadowfx)

# Installed side by side in a shared lib/, short names like libgl.a would mislead: libshadowfx_gl.a.
foreach(library report fxcontract fx scene assets lightspace gl render reload measure)
  set_target_properties(${library} PROPERTIES OUTPUT_NAME shadowfx_${library})
endforeach()
foreach(component report fxcontract fx scene assets lightspace gl render reload measure runtime)
  install(TARGETS ${component} EXPORT shadowfx-${component}
          ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
          INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/shadowfx)
  install(EXPORT shadowfx-${component} NAMESPACE shadowfx:: DESTINATION ${SHADOWFX_INSTALL_CMAKEDIR}
          FILE shadowfx-${component}-targets.cmake)
endforeach()
install(DIRECTORY ${PROJECT_SOURCE_DIR}/fx/include/fx DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/shadowfx)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/report/include/report DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/shadowfx)
foreach(library scene assets lightspace gl render reload measure)
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/runtime/${library}/include/runtime
          DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/shadowfx)
endforeach()
install(TARGETS shadowfx RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
# The runtime modules (runtime/RuntimeModules.h), where an installed program looks for them.
install(TARGETS shadowfx_meshimport shadowfx_raycast LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}/shadowfx)
# The compile worker (fx/CompileWorkers.h), where the installed fx library looks for it.
install(TARGETS shadowfx-compile-worker RUNTIME DESTINATION ${CMAKE_INSTALL_LIBEXECDIR})

configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/shadowfxConfig.cmake.in
  ${PROJECT_BINARY_DIR}/shadowfxConfig.cmake INSTALL_DESTINATION ${SHADOWFX_INSTALL_CMAKEDIR})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/shadowfxConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/shadowfxConfig.cmake ${PROJECT_BINARY_DIR}/shadowfxConfigVersion.cmake
        ${CMAKE_CURRENT_LIST_DIR}/FindSquish.cmake DESTINATION ${SHADOWFX_INSTALL_CMAKEDIR})
# The effect library (samples/shadowfx/EffectLibrary.h): the headers of effects/include, the shipped effects
# (stress's uniform reference among them) and the skeletons of `shadowfx new`, where the installed tool
# looks for them: share/shadowfx/effects. The goldens stay in the source tree: they belong to its CI.
set(SHADOWFX_INSTALL_EFFECTSDIR ${CMAKE_INSTALL_DATADIR}/shadowfx/effects)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/effects/include ${PROJECT_SOURCE_DIR}/effects/templates
        DESTINATION ${SHADOWFX_INSTALL_EFFECTSDIR})
file(GLOB SHADOWFX_SHIPPED_EFFECTS CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/effects/*.fx)
install(FILES ${SHADOWFX_SHIPPED_EFFECTS} DESTINATION ${SHADOWFX_INSTALL_EFFECTSDIR})
