# Run by ctest after the discovered tests (TEST_INCLUDE_FILES, tests/CMakeLists.txt): the COST of
# the longest tests, about their seconds of CPU on llvmpipe with a cold shader cache, so that
# `ctest -j N` starts them first. Without it a fresh build (no Testing/Temporary/CTestCostData.txt)
# runs tests in declaration order, and a minute-long test that starts last leaves the other cores
# idle; once a run has measured them, ctest orders by its own measurements instead.
set(glintlab_test_costs
  # The scenes every method renders on (every_method_scenes(), tests/builtin_scene_programs.hpp).
  "^Images/EveryMethodOnBuiltinScene\\.IsFinite/every_family( |$)" 60
  "^Images/EveryMethodOnBuiltinScene\\.IsFinite/glint_area_lights(_glinty)?( |$)" 40
  "^Images/EveryMethodOnBuiltinScene\\.IsFinite/gltf_showcase( |$)" 30
  "^PathMethods\\.AnEnvironmentByLobesIsTheSampledIntegralWithLessNoise$" 50
  "^PathMethods\\.SamplingTheFootprintNdfIntegratesWhatTheMethodEvaluates$" 30
  "^PathMethods\\.GlintyInterreflectionAgreesWithTheBruteForceFootprints$" 40
  "^DriverProfiles\\." 30
  "^Chermain\\.GeometricGlintAntiAliasing" 25
  "^Kneiphof\\.FiniteForRandomLightsAcrossTheHorizon" 25
  "^LtcAreaLightsSweep\\." 18
  "^Images/EveryMethodOnBuiltinScene\\.IsFinite/normal_glints_noise( |$)" 12
  "^Kneiphof\\.DenseGlintsConvergeToTheSmoothLtcRender" 12
  "^GltfMaterials\\.TexturedMaterialEqualsTheMaterialOfItsTexels" 11
  "^SpecularAA\\." 10
  "^Deng2022\\.MatchesYan2016AndTheReferenceNearAndFar" 9
  "^Report\\.ChromiumLoadsEveryImageAndVideoAndTheSliderMoves$" 7
  "^Methods/DefaultProgram\\." 6
  "^Images/EveryMethodOnBuiltinScene\\." 3
)

# Tests that compile the same forward programs (the same methods, material variants and light
# layout): each group shares a RESOURCE_LOCK, so that its tests run one after another and all but
# the first find the programs in the GL driver's shader cache (a fresh build's cache is empty; two
# tests that start together would both compile them, a minute of llvmpipe each).
set(glintlab_test_locks
  # a directional, a point and a spot light; textured and plain materials (two_quads in
  # tests/render/test_gltf_materials.cpp has the showcase's lights for this, and plane_under in
  # tests/render/test_spot_light.cpp dark lights of the other two kinds: every method in
  # EveryMethodShades on the plain material GltfMaterials' textured test draws).
  "^(Images/EveryMethodOnBuiltinScene\\.IsFinite/gltf_showcase|GltfMaterials\\.(TexturedMaterialEqualsTheMaterialOfItsTexels|EmissionAddsToTheTotal).*|SpotLight\\..*)( |$)" programs_showcase
  # a quad, a disk and a sphere light, a plain binomial-glints material (QuadLight's dark disk
  # and sphere light in tests/glsl/test_sampling.cpp).
  "^(Images/EveryMethodOnBuiltinScene\\.IsFinite/glint_area_lights(_glinty)?|QuadLight\\.EveryMethodRendersItFinite)( |$)" programs_area_lights
  # path:deng2022's programs of the steel floor under a sphere light (tests/render/test_path_methods.cpp).
  "^PathMethods\\.(SamplingTheFootprintNdfIntegratesWhatTheMethodEvaluates|GlintyInterreflectionAgreesWithTheBruteForceFootprints)$" programs_path_steel)

get_cmake_property(glintlab_variables VARIABLES)
foreach(list IN LISTS glintlab_variables)
  if(NOT list MATCHES "^test_.*_TESTS$")
    continue()
  endif()
  foreach(test IN LISTS ${list})
    set(rest ${glintlab_test_costs})
    while(rest)
      list(POP_FRONT rest pattern cost)
      if(test MATCHES "${pattern}")
        set_tests_properties("${test}" PROPERTIES COST ${cost})
        break()
      endif()
    endwhile()
    set(rest ${glintlab_test_locks})
    while(rest)
      list(POP_FRONT rest pattern lock)
      if(test MATCHES "${pattern}")
        set_tests_properties("${test}" PROPERTIES RESOURCE_LOCK ${lock})
      endif()
    endwhile()
  endforeach()
endforeach()
