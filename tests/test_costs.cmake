# Run by ctest after the discovered tests (TEST_INCLUDE_FILES, tests/CMakeLists.txt): the COST of
# the longest tests, about their seconds of CPU on llvmpipe with a cold shader cache, so that
# `ctest -j N` starts them first. Without it a fresh build (no Testing/Temporary/CTestCostData.txt)
# runs tests in declaration order, and a minute-long test that starts last leaves the other cores
# idle; once a run has measured them, ctest orders by its own measurements instead.
set(glintlab_test_costs
  "^Images/EveryMethodOnBuiltinScene\\.IsFinite/(quad_light|gltf_showcase)( |$)" 60
  "^GltfMaterials\\.TexturedMaterialEqualsTheMaterialOfItsTexels" 60
  "^Images/EveryMethodOnBuiltinScene\\.IsFinite/glint_area_lights" 45
  "^Shaders\\.EveryMethodAndPassCompiles" 35
  "^Chermain\\.GeometricGlintAntiAliasing" 40
  "^Images/EveryMethodOnBuiltinScene\\." 30
  "^SpotLight\\.HemisphereConeIsThePointLight$" 25
  "^SpecularAA\\.FilteringBeatsConventionalOnThinTubes$" 20
  "^Podee\\.BeatsConventionalOnTheNearMirrorScenes$" 20
  "^Reference\\.SubPixelHighlightOfAMirrorSphere" 15
  "^Cli\\.SameCommandWritesIdenticalFiles$" 15
  "^Report\\.ChromiumLoadsEveryImageAndVideoAndTheSliderMoves$" 12
  "^SpecularAA\\." 12
  "^QuadLight\\.EveryMethodRendersItFinite$" 12
  "^SpotLight\\.EveryMethodShades" 10
  "^Shaders\\.EveryChoiceOfACompileTimeParameterCompiles$" 10)

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
  endforeach()
endforeach()
