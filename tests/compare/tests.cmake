# porelab compare (docs/compare.md) and the stability guards (docs/stability.md).
set(PL_CMP tests/compare)

# The command runs a problem with its methods (two resolutions each) and writes its outputs.
pl_cli_test(compare_quick RC 0
  ARGS compare ${PL_CMP}/problems/wave.lua ${PL_CMP}/problems/buoyancy.lua --quick --out ${PL_CLI_OUT}/compare
  MATCH "darcy_explicit +cells along the rod = 10 "
  MATCH2 "\\| wave \\| darcy_"
  EXPECT_FILE ${PL_CLI_OUT}/compare/wave.png)
# The resolved models on the shared problems (two resolutions each): the fixed bed's
# permeability against Drummond & Tahir (1984) -- Stokes boundary elements within 10 % at 8
# elements per disc and 3 % at 16, Navier-Stokes within 10 % at h = 0.4 a; Darcy's Kozeny-Carman
# law 2.9 times too permeable -- and the settling disc by boundary elements within 7 % / 2 %
# of Faxen's speed.
pl_cli_test(compare_fixed_bed_quick RC 0
  ARGS compare ${PL_CMP}/problems/fixed_bed.lua --only stokes,darcy_kc --quick --out ${PL_CLI_OUT}/compare_fixed_bed
  MATCH "stokes +elements per disc = 16 +value [0-9.e-]+ +error 0.0[0-2][0-9]* "
  MATCH2 "darcy_kc +array spacings per mesh cell = 1 +value [0-9.e-]+ +error 1.8[0-9]* "
  EXPECT_FILE ${PL_CLI_OUT}/compare_fixed_bed/fixed_bed.png)
pl_cli_test(compare_fixed_bed_navier_stokes RC 0
  ARGS compare ${PL_CMP}/problems/fixed_bed.lua --only navier_stokes --quick --out ${PL_CLI_OUT}/compare_fixed_bed_ns
  MATCH "navier_stokes +mesh size on the discs / radius = 0.4 +value [0-9.e-]+ +error 0.0[0-4][0-9]* ")
pl_cli_test(compare_settling_stokes RC 0
  ARGS compare ${PL_CMP}/problems/settling.lua --only stokes --quick --out ${PL_CLI_OUT}/compare_settling_stokes
  MATCH "stokes +elements per disc = 8 +value [0-9.e-]+ +error 0.0[0-6][0-9]* "
  MATCH2 "stokes +elements per disc = 16 +value [0-9.e-]+ +error 0.0[0-1][0-9]* ")
# Terzaghi consolidation measured on grain columns (tests/compare/methods/grain_column.lua: a
# lattice of discs under a piston, its c_v from its own drained loading): u / u0 at the sealed
# end at T_v = 0.2 within 2 % of Terzaghi's series (Terzaghi 1925; Verruijt, Soil Mechanics,
# eq. 15.17: 0.7723) with 3 and 4 discs across. Over the whole ladder (3-12 discs) the errors
# were -0.74 % to +0.51 % (docs/compare.md). Without the coupling (FLUID_CONSOLIDATION 0) the
# same column gives u = 0, error 1: the criterion fails (compare_terzaghi_grains_uncoupled).
pl_cli_test(compare_terzaghi_grains RC 0
  ARGS compare ${PL_CMP}/problems/terzaghi.lua --only grain_column --quick --out ${PL_CLI_OUT}/compare_terzaghi
  MATCH "grain_column +discs across the column = 3 +value [0-9.e-]+ +error (0\\.0[01][0-9]*|[0-9.]+e-0[3-9]) "
  MATCH2 "grain_column +discs across the column = 4 +value [0-9.e-]+ +error (0\\.0[01][0-9]*|[0-9.]+e-0[3-9]) ")
pl_cli_test(compare_terzaghi_grains_uncoupled RC 0
  ARGS run ${PL_CMP}/guards/grain_column_uncoupled.lua --trust --quiet --out ${PL_CLI_OUT}/compare_terzaghi_uncoupled
  MATCH "error 1\n.*the criterion fails as it must: PASS")
pl_cli_test(compare_bad_problem RC 1 ARGS compare ${PL_CMP}/guards/servo_gain.lua --out ${PL_CLI_OUT}/compare_bad
  MATCH "servo_gain.lua: the problem table needs a name")
pl_cli_test(compare_usage RC 2 ARGS compare --bogus MATCH "unknown option '--bogus'")

# Stability sweeps: the measured failure boundary against the computed limit. The grain step in
# translation fails between 0.99 and 1.01 of the computed limit; the undrained staggering
# between 0.9 and 1.0 (the chart in docs/compare/ shows both sides).
# The grain step's coupled modes (docs/stability.md, "The grain step"): a disc sticking on a
# floor (sliding and turning, omega^2 = ks (1/m + r^2/I)) and a square sticking on its face
# (sliding and rocking on the area law's springs) fail between 0.99 and 1.01 of the computed step.
pl_cli_test(stability_grain_rotation RC 0
  ARGS compare ${PL_CMP}/stability/grain_rotation.lua ${PL_CMP}/stability/polygon_rocking.lua --out ${PL_CLI_OUT}/stability_rot
  MATCH "Grain step, rotation [^|]*\\| [0-9.e-]+ s \\| 0.99 \\| 1.01 \\|"
  MATCH2 "Grain step, polygon sticking [^|]*\\| [0-9.e-]+ s \\| 0.99 \\| 1.01 \\|")
pl_cli_test(stability_sweeps RC 0
  ARGS compare ${PL_CMP}/stability/grain_translation.lua ${PL_CMP}/stability/undrained_stagger.lua --out ${PL_CLI_OUT}/stability
  MATCH "Grain step, translation [^|]*\\| [0-9.e-]+ s \\| 0.99 \\| 1.01 \\|"
  MATCH2 "staggering [^|]*\\| [0-9.e-]+ s \\| 0.9[05]? \\| (0.95|1) \\|")

# The servo wall on one stiff contact fails between 0.99 and 1.01 of its computed gain limit
# 2 F / (k dt); a polygon face on the floor between 0.99 and 1.01 of the grain step's computed
# limit (the area law's face spring kn L / h, docs/stability.md); the Stokes drag coupling
# between 0.9 and 0.94 of 2 m / K; the explicit solid runs stably up to 0.99 of its critical
# step and is refused above it (docs/stability.md).
pl_cli_test(stability_sweeps_more RC 0
  ARGS compare ${PL_CMP}/stability/servo_gain.lua ${PL_CMP}/stability/polygon_area.lua
       ${PL_CMP}/stability/stokes_drag.lua ${PL_CMP}/stability/solid_step.lua --out ${PL_CLI_OUT}/stability_more
  MATCH "Servo wall [^|]*\\| 20 m/s \\| 0.99 \\| 1.01 \\|.*Grain step, polygon on [^|]*\\| [0-9.e-]+ s \\| 0.99 \\| 1.01 \\|"
  MATCH2 "Stokes drag coupling [^|]*\\| [0-9.e-]+ s \\| 0.9 \\| 0.94 \\|.*Explicit FE solid [^|]*\\| [0-9.e-]+ s \\| 0.99 \\| 1.01 \\| refused")

# The Navier-Stokes drag coupling (label navier_stokes; ~20 s CPU): stable up to the computed
# relaxation limit 2 / (1 + D tau / m), failing between 1.0 and 1.2 of it (measured 1 / 1.05).
get_target_property(_pl_cmp_defs porelab_engine INTERFACE_COMPILE_DEFINITIONS)
if("${_pl_cmp_defs}" MATCHES "PL_HAVE_GMSH=1")
  pl_cli_test(stability_ns_drag RC 0
    ARGS compare ${PL_CMP}/stability/ns_drag.lua --out ${PL_CLI_OUT}/stability_ns
    MATCH "Navier–Stokes drag coupling [^|]*\\| [0-9.]+ \\| (0.95|1) \\| (1.05|1.1|1.2) \\|")
  set_tests_properties(cli_stability_ns_drag PROPERTIES LABELS "cli;navier_stokes" TIMEOUT 300)
endif()

# Each run-time limit: past it the message names what, where and the safe setting.
pl_cli_test(guard_grain_step RC 1 ARGS run tests/cli/bad/unstable.lua --quiet --out ${PL_CLI_OUT}/guard_grain
  MATCH "unstable: .*critical step .*a safe step is [0-9.e-]+ s")
pl_cli_test(guard_servo_gain RC 1 ARGS run ${PL_CMP}/guards/servo_gain.lua --quiet --out ${PL_CLI_OUT}/guard_servo
  MATCH "unstable servo: body 3 .*G k dt / F = 20 exceeds its stability limit 2 .*a safe gain is G <= F / \\(k dt\\) = 10 m/s")
pl_cli_test(guard_polygon_step RC 1 ARGS run ${PL_CMP}/guards/polygon_step.lua --quiet --out ${PL_CLI_OUT}/guard_polygon
  MATCH "unstable: .*likely cause: the time step [0-9.e-]+ s is 1.2 times the critical step [0-9.e-]+ s \\(body 2, polygon face\\).*a safe step is [0-9.e-]+ s")
pl_cli_test(guard_stokes_drag RC 1 ARGS run ${PL_CMP}/guards/stokes_drag.lua --quiet --out ${PL_CLI_OUT}/guard_stokes_drag
  MATCH "stokes: explicit drag unstable .*needs solve_every x dt < 2 min\\(m/K, I/K_rot\\) = 0.00248[0-9]* s, but it is 1 x 0.003 s; use dt <= [0-9.e-]+ s")
pl_cli_test(guard_solid_step RC 1 ARGS run ${PL_CMP}/guards/solid_step.lua --quiet --out ${PL_CLI_OUT}/guard_solid
  MATCH "solid: the time step 2e-06 s exceeds the critical step 1.09[0-9]*e-06 s of element [0-9]+ .*Set dt <= [0-9.e-]+ s")
pl_cli_test(guard_servo_gain_safe RC 0 ARGS run ${PL_CMP}/guards/servo_gain_safe.lua --quiet --out ${PL_CLI_OUT}/guard_servo_safe)
pl_cli_test(guard_stagger RC 1 ARGS run ${PL_CMP}/guards/stagger.lua --quiet --out ${PL_CLI_OUT}/guard_stagger
  MATCH "undrained grain-water coupling is past its staggering limit .*0.0001 s x 4 .*safe: a grain step dt <= [0-9.e-]+ s with FLUID_SOLVE_TIMESTEPS 1, or FLUID_BULK_MODULUS <= [0-9.e+]+ Pa")
pl_cli_test(guard_stagger_safe RC 0 ARGS run ${PL_CMP}/guards/stagger_safe.lua --quiet --out ${PL_CLI_OUT}/guard_stagger_safe)
pl_cli_test(guard_explicit_darcy RC 1 ARGS run ${PL_CMP}/guards/explicit_safety.lua --quiet --out ${PL_CLI_OUT}/guard_explicit
  MATCH "explicit_safety must be .*\\[0.001, 1\\]")

# The explicit Darcy update driven past its computed limit (the table refuses
# FLUID_EXPLICIT_SAFETY > 1, so the test sets the kernel's factor itself).
pl_add_c_test(test_stability_explicit_darcy SOURCES ${PL_TEST_DIR}/compare/test_stability_explicit_darcy.c
  LABEL fluid TIMEOUT 60)
target_include_directories(test_stability_explicit_darcy PRIVATE ${CMAKE_SOURCE_DIR}/app ${CMAKE_SOURCE_DIR}/app/render ${CHOLMOD_INCLUDE})
target_link_libraries(test_stability_explicit_darcy PRIVATE porelab_render)

# fluid = "auto": the choice pinned on eight scenes (porelab info prints it with the reasons).
foreach(case "floating;buoyancy: hydrostatic: no flow expected"
             "buoyancy_head;buoyancy: darcy, [0-9]+ elements: a head difference of 0.05 m drives flow"
             "seepage;seepage: darcy, [0-9]+ elements: seepage forces at Re_p = [0-9.]+ < 10"
             "fast_seepage;seepage: darcy, [0-9]+ elements: Re_p = [0-9.e+]+ is past Darcy's range .*navier_stokes resolves it"
             "undrained;pore_pressure: darcy\\+consolidation, [0-9]+ elements: t_c = [0-9.e+]+ s is [0-9.e+]+ times the duration 2 s.*\\(undrained\\)"
             "drained;pore_pressure: hydrostatic: drained: excess pore pressure dissipates in t_c = [0-9.e-]+ s"
             "between;flow_between_grains: stokes, gap 0.001 m, a lid at the water level closes the tank, grain step <= [0-9.e-]+ s \\(half the drag limit 2 m/K\\): .*at Re_p = [0-9.e-]+ < 1 inertia is negligible"
             "between_fast;flow_between_grains: navier_stokes, mesh [0-9.e-]+ m on the grains, open top: .*at Re_p = [0-9.e+]+ >= 1 inertia matters")
  list(GET case 0 scene)
  list(GET case 1 expect)
  pl_cli_test(auto_${scene} RC 0 ARGS info ${PL_CMP}/auto/${scene}.lua
    MATCH "fluid auto +needs ${expect}" MATCH2 "rejected: ")
endforeach()
pl_cli_test(auto_run_summary RC 0 ARGS run ${PL_CMP}/auto/floating.lua --steps 50 --quiet --out ${PL_CLI_OUT}/auto_run
  MATCH "fluid auto +needs buoyancy: hydrostatic")
pl_cli_test(auto_imperative RC 0 ARGS run ${PL_CMP}/auto/imperative.lua --quiet --out ${PL_CLI_OUT}/auto_imp
  MATCH "imperative auto: water level 0.3 m" MATCH2 "fluid auto +needs buoyancy: hydrostatic")
pl_cli_test(auto_bad_fluid RC 1 ARGS info ${PL_CMP}/auto/bad_fluid.lua
  MATCH "bad_fluid.lua:2: world: fluid must be \"auto\" .*\\(got magic\\)")
pl_cli_test(auto_bad_needs RC 1 ARGS info ${PL_CMP}/auto/bad_needs.lua
  MATCH "bad_needs.lua:2: world: needs must be \"buoyancy\", \"seepage\", \"pore_pressure\" or \"flow_between_grains\" \\(got 'everything'\\)")
# A scene that fixes Darcy past its assumptions gets a warning with the number and the model
# to use instead.
pl_cli_test(auto_warn_darcy_re RC 0 ARGS info scenes/lab/buoyancy_darcy.lua
  MATCH "warning +Darcy at a particle Reynolds number Re_p = [0-9.e+]+ .*suggested model: hydrostatic")
pl_cli_test(auto_warn_stokes_re RC 0 ARGS info ${PL_CMP}/auto/stokes_inertia.lua
  MATCH "warning +Stokes flow at a particle Reynolds number Re_p = 6.68e\\+03 .*suggested model: navier_stokes")
# the resolved models chosen by auto set up and step (two steps each)
pl_cli_test(auto_run_stokes RC 0 ARGS run ${PL_CMP}/auto/between.lua --steps 2 --quiet --out ${PL_CLI_OUT}/auto_stokes
  MATCH "fluid auto +needs flow_between_grains: stokes")
pl_cli_test(auto_run_navier_stokes RC 0 ARGS run ${PL_CMP}/auto/between_fast.lua --steps 2 --quiet --out ${PL_CLI_OUT}/auto_ns
  MATCH "fluid auto +needs flow_between_grains: navier_stokes")

# docs/compare/ and the tables of docs/compare.md, regenerated by one command:
#   cmake --build build --target compare_docs
# (every problem with every method, the stability sweeps, the explicit Darcy sweep's chart).
add_custom_target(compare_docs
  COMMAND $<TARGET_FILE:porelab> compare tests/compare/problems/buoyancy.lua tests/compare/problems/settling.lua
          tests/compare/problems/fixed_bed.lua
          tests/compare/problems/wave.lua tests/compare/problems/terzaghi.lua tests/compare/problems/restitution.lua
          tests/compare/problems/energy.lua tests/compare/stability/grain_translation.lua
          tests/compare/stability/grain_rotation.lua tests/compare/stability/polygon_area.lua
          tests/compare/stability/polygon_rocking.lua
          tests/compare/stability/undrained_stagger.lua tests/compare/stability/servo_gain.lua
          tests/compare/stability/stokes_drag.lua tests/compare/stability/ns_drag.lua
          tests/compare/stability/solid_step.lua
          --out docs/compare --update-doc docs/compare.md
  COMMAND $<TARGET_FILE:test_stability_explicit_darcy> docs/compare
  WORKING_DIRECTORY ${CMAKE_SOURCE_DIR}
  DEPENDS porelab test_stability_explicit_darcy
  USES_TERMINAL)
