# vtkRayTracedVisibility checked against closed forms (hard shadow, sphere-light and directional
# penumbrae, caster exclusion). Included by Testing/Cxx/CMakeLists.txt; renders, so ctest must run
# under a display (xvfb-run).
add_executable(TestRayTracedVisibility TestRayTracedVisibility.cxx)
target_link_libraries(TestRayTracedVisibility
  PRIVATE
    penumbra_test_harness
    Penumbra::Geometry
    VTK::CommonCore
    VTK::CommonDataModel
    VTK::FiltersSources
    VTK::InteractionStyle
    VTK::RenderingCore
    VTK::RenderingFreeType
    VTK::RenderingOpenGL2
    glm::glm)
vtk_module_autoinit(
  TARGETS TestRayTracedVisibility
  MODULES VTK::RenderingOpenGL2 VTK::InteractionStyle VTK::RenderingFreeType)
add_test(NAME RayTracedVisibility COMMAND TestRayTracedVisibility)
set_tests_properties(RayTracedVisibility PROPERTIES TIMEOUT 120 LABELS "rendering;raytracing")
