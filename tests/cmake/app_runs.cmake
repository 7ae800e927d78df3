# catena run, check and the integrators on small scenes: options, dynamics, reactions,
# multistep methods, pantographs on a wire, summaries, stats of steps, the PETSc TS bridge.
# Included by tests/CMakeLists.txt, whose helpers (catena_app_test, catena_app_check) and
# variables (app, expect, mpi_env) it uses.

# A PETSc option no solver read is reported (a misspelling); one that was read is not.
catena_app_test(run_reports_unused_petsc_option 0
                "catena: warning: PETSc option -hht_snes_rtoll was not used: misspelt"
                ${app} run meshes/cable_pendulum.yaml --set analysis.duration=0.01
                -hht_snes_rtoll 1e-3 -o ${CMAKE_CURRENT_BINARY_DIR}/app_unused_option.h5)
catena_app_test(run_used_petsc_option_not_reported 1 "^0$"
                sh -c "${app} run meshes/cable_pendulum.yaml --set analysis.duration=0.01 -hht_snes_rtol 1e-8 -log_view -o ${CMAKE_CURRENT_BINARY_DIR}/app_used_option.h5 2>&1 | grep -c 'was not used'")
# A PETSc option whose value PETSc refuses is bad input (exit 2) named with its value and
# PETSc's reason, and PETSc prints no traceback of its own.
catena_app_test(run_bad_petsc_type_exit_2 2
                "'-hht_pc_type nosuchpc': PETSc refused this option: Unable to find requested PC type nosuchpc"
                ${app} run meshes/cable_pendulum.yaml --set analysis.duration=0.01
                -hht_pc_type nosuchpc -o ${CMAKE_CURRENT_BINARY_DIR}/app_bad_pc_type.h5)
catena_app_test(run_bad_petsc_integer_exit_2 2
                "'-hht_snes_max_it 2.5': PETSc refused this option: Input string 2.5 has no integer value"
                ${MPIEXEC_EXECUTABLE} -n 2 --oversubscribe ${app} run meshes/cable_pendulum.yaml
                --set analysis.duration=0.01 -hht_snes_max_it 2.5
                -o ${CMAKE_CURRENT_BINARY_DIR}/app_bad_max_it.h5)
catena_app_test(run_bad_petsc_option_no_traceback 1 "^0$"
                sh -c "${app} run meshes/cable_pendulum.yaml --set analysis.duration=0.01 -hht_ksp_type nosuchksp -o ${CMAKE_CURRENT_BINARY_DIR}/app_bad_ksp_type.h5 2>&1 | grep -c 'PETSC ERROR'")
# The static stability check reads its own MUMPS options (-static_stability_), not Newton's.
catena_app_test(static_stability_options_used 1 "^0$"
                sh -c "${app} run meshes/hanging_cable.yaml -static_stability_mat_mumps_icntl_14 30 -o ${CMAKE_CURRENT_BINARY_DIR}/app_stability_option.h5 2>&1 | grep -c 'was not used'")
catena_app_test(check_default 0 "valid" ${app} check meshes/default.yaml)
# A scene saved with CR alone as line break reads as with LF (YAML 1.2, section 5.4).
catena_app_test(check_cr_line_breaks 0 "cable_pendulum_cr.yaml: valid"
                ${app} check tests/data/app/cable_pendulum_cr.yaml)
# Field samples: faster than 1 MHz, or more than 10^7 of them, are refused (an interval of
# 1e-9 s wrote 6.7 GB in a minute).
catena_app_test(check_output_interval_too_short_exit_2 2
                "'output.interval': output.interval = 1e-09 s is below 1e-6 s"
                ${app} check meshes/pantograph_wire.yaml --set output.interval=1e-9)
catena_app_test(check_too_many_samples_exit_2 2
                "'output.interval': output.interval = 1e-06 s over 100 s makes 1e\\+08 field samples. accepted: at most 1e7"
                ${app} check meshes/pantograph_wire.yaml --set output.interval=1e-6
                --set analysis.duration=100)
# A pantograph that starts before its path is warned of, as one that runs past its end.
catena_app_test(check_pantograph_starts_off_path 0
                "warning: pantograph 'leading' starts off its path \\(at -5 m. the path runs from 0 to [0-9.]+ m\\) and touches nothing until t = "
                ${app} check meshes/pantograph_wire.yaml --set pantographs[0].start=-5)
# The command line: an empty -o, an option where a value belongs, an option given twice.
catena_app_test(run_empty_output_exit_2 2 "'-o': no file name given"
                sh -c "${app} run meshes/cable_pendulum.yaml -o ''")
catena_app_test(sweep_option_as_value_exit_2 2
                "'--vary': missing value after --vary \\(the next argument is the option '-o'\\)"
                ${app} sweep meshes/pantograph_wire.yaml --vary -o DIR)
catena_app_test(elasticity_span_twice_exit_2 2 "'--span': '--span' is given twice"
                ${app} elasticity meshes/simple_catenary.yaml --span 1 --span 2)
catena_app_test(run_default_np2 0 "output: .*app_default.h5"
                ${MPIEXEC_EXECUTABLE} -n 2 --oversubscribe ${app} run meshes/default.yaml
                -o ${CMAKE_CURRENT_BINARY_DIR}/app_default.h5)
catena_app_test(run_hanging_cable 0 "static equilibrium" ${app} run meshes/hanging_cable.yaml
                -o ${CMAKE_CURRENT_BINARY_DIR}/app_hanging.h5)
catena_app_test(bad_scene_exit_2 2 "zero_EA.yaml:[0-9]+: 'sections.*EA'"
                ${app} check tests/data/bad_scenes/zero_EA.yaml)
catena_app_test(bad_override_exit_2 2 "did you mean"
                ${app} check meshes/default.yaml --set output.fiel=x.h5)
catena_app_test(missing_file_exit_2 2 "no_such_scene.yaml: cannot read scene: no such file"
                ${app} check no_such_scene.yaml)
# A directory or a device as the scene is named as such (a device was read without end: the
# process grew until the kernel killed it; a pipe blocked), on every rank count.
catena_app_test(directory_as_scene 2 "meshes: cannot read scene: this is a directory" ${app}
                check meshes)
catena_app_test(device_as_scene_np2 2 "/dev/zero: cannot read scene: not a regular file"
                ${MPIEXEC_EXECUTABLE} -n 2 --oversubscribe ${app} check /dev/zero)
catena_app_test(no_free_unknown 2 "all_coordinates_held.yaml: 'supports': the scene leaves no unknown free"
                ${app} run tests/data/app/all_coordinates_held.yaml
                -o ${CMAKE_CURRENT_BINARY_DIR}/app_no_free_unknown.h5)
# Catena's options take two dashes: a misspelt one is refused, not passed to PETSc (a run
# with --restrat would start afresh over the output it was to continue).
catena_app_test(misspelt_option 2 "unknown option '--restrat' for run. accepted: .*--restart"
                ${app} run meshes/pantograph_wire.yaml --restrat
                -o ${CMAKE_CURRENT_BINARY_DIR}/app_misspelt_option.h5)
catena_app_test(unknown_command_exit_2 2 "unknown command" ${app} frobnicate)
catena_app_test(mechanism_exit_3 3 "singular.*mechanism"
                ${MPIEXEC_EXECUTABLE} -n 2 --oversubscribe ${app} run tests/data/app/mechanism.yaml
                -o ${CMAKE_CURRENT_BINARY_DIR}/app_mechanism.h5)
# Dynamics: the issue's command, every integrator family on the pendulum (0.1 s), the other
# scenes, and an unreachable tolerance ending with exit 3 and a valid, closed output file.
catena_app_test(run_cable_pendulum_radau3_np2 0 "done at t = 1 s"
                ${MPIEXEC_EXECUTABLE} -n 2 --oversubscribe ${app} run meshes/cable_pendulum.yaml
                --set integrator.type=radau --set integrator.stages=3
                -o ${CMAKE_CURRENT_BINARY_DIR}/app_pendulum.h5)
foreach(type hht gauss lobatto_iiia lobatto_iiic sdirk)
  catena_app_test(run_cable_pendulum_${type} 0 "done at t = 0.1 s"
                  ${app} run meshes/cable_pendulum.yaml --set integrator.type=${type}
                  --set analysis.duration=0.1
                  -o ${CMAKE_CURRENT_BINARY_DIR}/app_pendulum_${type}.h5)
endforeach()
catena_app_test(run_cable_pendulum_adaptive 0 "done at t = 0.2 s"
                ${app} run meshes/cable_pendulum.yaml --set integrator.type=radau
                --set integrator.adaptive=true --set integrator.rtol=1e-6
                --set integrator.atol=1e-8 --set analysis.duration=0.2
                -o ${CMAKE_CURRENT_BINARY_DIR}/app_pendulum_adaptive.h5)
catena_app_test(run_taut_string_np2 0 "done at t = 5 s"
                ${MPIEXEC_EXECUTABLE} -n 2 --oversubscribe ${app} run meshes/taut_string.yaml
                -o ${CMAKE_CURRENT_BINARY_DIR}/app_taut_string.h5)
set_tests_properties(app_run_taut_string_np2 PROPERTIES FIXTURES_SETUP taut_string_run)
# The supports' reactions over time: each end pulls with the wire's 20 kN tension.
catena_app_check(taut_string_reactions "taut_string_run" check_reactions.py
                 ${CMAKE_CURRENT_BINARY_DIR}/app_taut_string.h5 20000 0.01)
# analysis.structure: linear on the plucked string at np 2: the linear closed form, one
# Newton iteration per step, and the amplitude-dependent drift of the nonlinear run.
catena_app_test(run_taut_string_linear_np2 0 "structure: linear about the static equilibrium: 60 cable"
                ${MPIEXEC_EXECUTABLE} -n 2 --oversubscribe ${app} run meshes/taut_string.yaml
                --set analysis.structure=linear
                -o ${CMAKE_CURRENT_BINARY_DIR}/app_taut_string_linear.h5)
set_tests_properties(app_run_taut_string_linear_np2 PROPERTIES FIXTURES_SETUP taut_string_linear)
catena_app_check(taut_string_linear_check "taut_string_linear;taut_string_run"
                 check_linear_structure.py
                 ${CMAKE_CURRENT_BINARY_DIR}/app_taut_string_linear.h5
                 ${CMAKE_CURRENT_BINARY_DIR}/app_taut_string.h5)
# Central differences on the plucked string just below their stability limit (5.34e-5 s):
# the linear structure against the closed form, the nonlinear one against Radau IIA's run
# above; a step past the limit is refused before the first step (the limit from the
# structure's highest frequency at the initial state, test_solvers_central_difference).
set(cd_string --set integrator.type=central_difference --set integrator.stages=~
    --set integrator.dt=5e-5 --set analysis.duration=1)
catena_app_test(run_taut_string_central_difference_linear_np2 0 "dynamics: central_difference"
                ${MPIEXEC_EXECUTABLE} -n 2 --oversubscribe ${app} run meshes/taut_string.yaml
                ${cd_string} --set analysis.structure=linear
                -o ${CMAKE_CURRENT_BINARY_DIR}/app_taut_string_cd_linear.h5)
set_tests_properties(app_run_taut_string_central_difference_linear_np2 PROPERTIES
                     FIXTURES_SETUP taut_string_cd_linear)
catena_app_test(run_taut_string_central_difference 0 "stability limit: steps up to 5\\.339[0-9]*e-05 s \\(a longer fixed step is refused\\)"
                ${app} run meshes/taut_string.yaml ${cd_string}
                -o ${CMAKE_CURRENT_BINARY_DIR}/app_taut_string_cd.h5)
set_tests_properties(app_run_taut_string_central_difference PROPERTIES
                     FIXTURES_SETUP taut_string_cd)
catena_app_check(taut_string_central_difference_check
                 "taut_string_cd_linear;taut_string_cd;taut_string_run"
                 check_central_difference.py
                 ${CMAKE_CURRENT_BINARY_DIR}/app_taut_string_cd_linear.h5
                 ${CMAKE_CURRENT_BINARY_DIR}/app_taut_string_cd.h5
                 ${CMAKE_CURRENT_BINARY_DIR}/app_taut_string.h5)
# The multistep integrators on the plucked string (test_solvers_multistep has their orders
# and stability on the oscillator): Park's method at two steps, one run on 2 ranks, and
# adaptive BDF-2, against Radau IIA's run of the scene.
set(ms_string --set integrator.stages=~ --set analysis.duration=1)
catena_app_test(run_taut_string_park_np2 0 "dynamics: park, fixed step 0\\.01 s"
                ${MPIEXEC_EXECUTABLE} -n 2 --oversubscribe ${app} run meshes/taut_string.yaml
                ${ms_string} --set integrator.type=park --set integrator.dt=0.01
                -o ${CMAKE_CURRENT_BINARY_DIR}/app_taut_string_park.h5)
set_tests_properties(app_run_taut_string_park_np2 PROPERTIES FIXTURES_SETUP taut_string_park)
catena_app_test(run_taut_string_park_half 0 "dynamics: park, fixed step 0\\.005 s"
                ${app} run meshes/taut_string.yaml ${ms_string} --set integrator.type=park
                --set integrator.dt=0.005
                -o ${CMAKE_CURRENT_BINARY_DIR}/app_taut_string_park_half.h5)
set_tests_properties(app_run_taut_string_park_half PROPERTIES FIXTURES_SETUP taut_string_park_half)
catena_app_test(run_taut_string_bdf_adaptive 0 "dynamics: bdf\\(order=2\\), adaptive"
                ${app} run meshes/taut_string.yaml ${ms_string} --set integrator.type=bdf
                --set integrator.adaptive=true --set integrator.rtol=1e-5
                --set integrator.atol=1e-7 --set integrator.dt=1e-3
                -o ${CMAKE_CURRENT_BINARY_DIR}/app_taut_string_bdf.h5)
set_tests_properties(app_run_taut_string_bdf_adaptive PROPERTIES FIXTURES_SETUP taut_string_bdf)
# Adams-Bashforth-Moulton (PECE, explicit) just below its stability limit 1.28/omega_max,
# and a step past it refused before the first step.
catena_app_test(run_taut_string_abm_np2 0 "stability limit: steps up to 3\\.417[0-9]*e-05 s"
                ${MPIEXEC_EXECUTABLE} -n 2 --oversubscribe ${app} run meshes/taut_string.yaml
                --set integrator.stages=~ --set analysis.duration=0.5 --set integrator.type=abm
                --set integrator.dt=2.5e-5 -o ${CMAKE_CURRENT_BINARY_DIR}/app_taut_string_abm.h5)
set_tests_properties(app_run_taut_string_abm_np2 PROPERTIES FIXTURES_SETUP taut_string_abm)
catena_app_test(abm_step_past_its_limit 2
                "dt = 3\\.5e-05 s is too long: Adams-Bashforth-Moulton of order 2 \\(PECE\\) is stable for steps up to 1\\.28/max\\(omega_max, nu_max\\) = 3\\.417"
                ${app} run meshes/taut_string.yaml ${ms_string} --set integrator.type=abm
                --set integrator.dt=3.5e-5 -o ${CMAKE_CURRENT_BINARY_DIR}/app_abm_refused.h5)
catena_app_test(abm_takes_no_newton_tolerance 2
                "integrator\\.newton_rtol.*'newton_rtol' does not apply to abm \\(explicit"
                ${app} run meshes/taut_string.yaml ${ms_string} --set integrator.type=abm
                --set integrator.dt=2.5e-5 --set integrator.newton_rtol=1e-6
                -o ${CMAKE_CURRENT_BINARY_DIR}/app_abm_refused.h5)
catena_app_check(taut_string_multistep_check
                 "taut_string_park;taut_string_park_half;taut_string_bdf;taut_string_abm;taut_string_run"
                 check_multistep.py
                 ${CMAKE_CURRENT_BINARY_DIR}/app_taut_string_park.h5
                 ${CMAKE_CURRENT_BINARY_DIR}/app_taut_string_park_half.h5
                 ${CMAKE_CURRENT_BINARY_DIR}/app_taut_string_bdf.h5
                 ${CMAKE_CURRENT_BINARY_DIR}/app_taut_string_abm.h5
                 ${CMAKE_CURRENT_BINARY_DIR}/app_taut_string.h5)
# What the scene reader refuses for the multistep types, with the key and the reason.
catena_app_test(bdf_order_above_2_needs_adaptive 2
                "integrator\\.order.*bdf of order 3 needs adaptive: true"
                ${app} run meshes/taut_string.yaml ${ms_string} --set integrator.type=bdf
                --set integrator.order=3 -o ${CMAKE_CURRENT_BINARY_DIR}/app_bdf_refused.h5)
catena_app_test(bdf_refuses_step_doubling 2
                "integrator\\.error_estimate.*bdf is a multistep method: step doubling"
                ${app} run meshes/taut_string.yaml ${ms_string} --set integrator.type=bdf
                --set integrator.adaptive=true
                --set integrator.error_estimate=step_doubling
                -o ${CMAKE_CURRENT_BINARY_DIR}/app_bdf_refused.h5)
catena_app_test(order_applies_to_bdf_only 2
                "integrator\\.order.*'order' applies to integrator types bdf and abm only"
                ${app} run meshes/taut_string.yaml ${ms_string} --set integrator.type=park
                --set integrator.order=2 -o ${CMAKE_CURRENT_BINARY_DIR}/app_bdf_refused.h5)
catena_app_test(central_difference_step_past_its_limit 2
                "dt = 5\\.4e-05 s is too long: central differences are stable for steps up to 2/omega_max = 5\\.339[0-9]*e-05 s, omega_max = 3745[0-9.]* rad/s, the structure's highest frequency"
                ${app} run meshes/taut_string.yaml --set integrator.type=central_difference
                --set integrator.stages=~ --set integrator.dt=5.4e-5
                -o ${CMAKE_CURRENT_BINARY_DIR}/app_taut_string_cd_refused.h5)
# direction: backward — the pantograph on a wire from 55 m toward 0 is the mirror image of
# the one from 5 m toward 60 m (the wire is symmetric): positions mirrored, contact forces
# equal to the Newton tolerance; nonlinear (backward on 2 ranks) and modal.
catena_app_test(run_pantograph_wire_forward 0 "done at t = 0.5 s"
                ${app} run meshes/pantograph_wire.yaml --set analysis.duration=0.5
                -o ${CMAKE_CURRENT_BINARY_DIR}/app_pw_forward.h5)
set_tests_properties(app_run_pantograph_wire_forward PROPERTIES FIXTURES_SETUP pw_forward)
catena_app_test(run_pantograph_wire_backward_np2 0 "done at t = 0.5 s"
                ${MPIEXEC_EXECUTABLE} -n 2 --oversubscribe ${app} run meshes/pantograph_wire.yaml
                --set analysis.duration=0.5 --set pantographs[0].start=55
                --set pantographs[0].direction=backward
                -o ${CMAKE_CURRENT_BINARY_DIR}/app_pw_backward.h5)
set_tests_properties(app_run_pantograph_wire_backward_np2 PROPERTIES FIXTURES_SETUP pw_backward)
catena_app_check(pantograph_wire_backward_check "pw_forward;pw_backward"
                 check_backward_pantograph.py ${CMAKE_CURRENT_BINARY_DIR}/app_pw_forward.h5
                 ${CMAKE_CURRENT_BINARY_DIR}/app_pw_backward.h5 60 1e-6)
foreach(direction forward backward)
  set(start 5)
  if(direction STREQUAL "backward")
    set(start 55)
  endif()
  # 501 field samples and the end's checkpoint (q and v together, then a): 503 fields
  # rebuilt from the modes, none for the 2 500 steps (each rebuild reads all the shapes).
  catena_app_test(run_pantograph_wire_modal_${direction} 0
                  "field rebuilt from the modes 503 times"
                  ${app} run meshes/pantograph_wire.yaml --set analysis.duration=0.5
                  --set analysis.structure=modal --set analysis.modal_cutoff=100
                  --set pantographs[0].start=${start} --set pantographs[0].direction=${direction}
                  -o ${CMAKE_CURRENT_BINARY_DIR}/app_pw_modal_${direction}.h5)
  set_tests_properties(app_run_pantograph_wire_modal_${direction} PROPERTIES
                       FIXTURES_SETUP pw_modal_${direction})
endforeach()
catena_app_check(pantograph_wire_modal_backward_check "pw_modal_forward;pw_modal_backward"
                 check_backward_pantograph.py ${CMAKE_CURRENT_BINARY_DIR}/app_pw_modal_forward.h5
                 ${CMAKE_CURRENT_BINARY_DIR}/app_pw_modal_backward.h5 60 1e-6)
catena_app_test(check_pantograph_backward 0
                "27.7778 m/s \\(100 km/h\\) backward \\(toward decreasing arc length\\), start 55 m"
                ${app} check meshes/pantograph_wire.yaml --set pantographs[0].direction=backward
                --set pantographs[0].start=55)
# Without an evaluation section the run's summary gives each pantograph its own stretch
# (two trains on one wire, toward each other; they had the first one's).
catena_app_test(run_two_trains_own_stretches 0 "backward_one over \\[106\\.667, 115\\] m: mean"
                ${app} run tests/data/app/two_trains_wire.yaml
                -o ${CMAKE_CURRENT_BINARY_DIR}/app_two_trains_wire.h5)
catena_app_test(pantograph_direction_unknown 2
                "pantographs\\[0\\]\\.direction.*unknown direction 'sideways'.*accepted: forward .* or backward"
                ${app} check meshes/pantograph_wire.yaml --set pantographs[0].direction=sideways)

# analysis.structure: modal (the catenary's modes below the cut-off with the static
# correction, contact and slack droppers as forces) against the linear structure: the
# pantograph on a wire at np 1 and 2 (docs/integrators.md, "Modal model": RMS difference
# 0.52 % of the mean force, sigma +0.07 %), and a catenary whose droppers go slack under a
# 300 N pantograph at 300 km/h (1.8 %, +0.13 %, slack dropper samples 6122 / 6135).
catena_app_test(run_pantograph_wire_linear 0 "done at t = 1.5 s"
                ${app} run meshes/pantograph_wire.yaml --set analysis.structure=linear
                -o ${CMAKE_CURRENT_BINARY_DIR}/app_pw_linear.h5)
set_tests_properties(app_run_pantograph_wire_linear PROPERTIES FIXTURES_SETUP pw_linear)
# The np 1 run writes its modes to a modal basis (analysis.modal_basis), removed first so
# that it is written anew; an np 2 run reads them (checked against its structure) and
# must give the np 1 run's answer; a scene with another tension refuses them.
add_test(NAME app_pw_basis_removed
         COMMAND ${CMAKE_COMMAND} -E rm -f ${CMAKE_CURRENT_BINARY_DIR}/app_pw_basis.h5)
set_tests_properties(app_pw_basis_removed PROPERTIES LABELS app FIXTURES_SETUP pw_basis_removed)
catena_app_test(run_pantograph_wire_modal 0 "modal model: 175 modes.*written to .*app_pw_basis.h5"
                ${app} run meshes/pantograph_wire.yaml --set analysis.structure=modal
                --set analysis.modal_cutoff=100
                --set analysis.modal_basis=${CMAKE_CURRENT_BINARY_DIR}/app_pw_basis.h5
                -o ${CMAKE_CURRENT_BINARY_DIR}/app_pw_modal.h5)
set_tests_properties(app_run_pantograph_wire_modal PROPERTIES FIXTURES_SETUP pw_modal
                     FIXTURES_REQUIRED pw_basis_removed)
catena_app_test(run_pantograph_wire_modal_from_basis_np2 0
                "modal model: 175 modes.*read from .*app_pw_basis.h5 and checked"
                ${MPIEXEC_EXECUTABLE} -n 2 --oversubscribe ${app} run meshes/pantograph_wire.yaml
                --set analysis.structure=modal --set analysis.modal_cutoff=100
                --set analysis.modal_basis=${CMAKE_CURRENT_BINARY_DIR}/app_pw_basis.h5
                -o ${CMAKE_CURRENT_BINARY_DIR}/app_pw_modal_from_basis_np2.h5)
set_tests_properties(app_run_pantograph_wire_modal_from_basis_np2 PROPERTIES
                     FIXTURES_SETUP pw_modal_from_basis FIXTURES_REQUIRED pw_modal)
catena_app_check(pantograph_wire_modal_basis_check "pw_linear;pw_modal;pw_modal_from_basis"
                 check_modal_structure.py ${CMAKE_CURRENT_BINARY_DIR}/app_pw_linear.h5
                 ${CMAKE_CURRENT_BINARY_DIR}/app_pw_modal.h5 0.01 0.005
                 ${CMAKE_CURRENT_BINARY_DIR}/app_pw_modal_from_basis_np2.h5)
catena_app_test(pantograph_wire_modal_basis_of_another_structure 2
                "app_pw_basis.h5: 'analysis.modal_basis': the modes in this file are not this scene's: mode 1 .* relative residual"
                ${app} run meshes/pantograph_wire.yaml --set analysis.structure=modal
                --set analysis.modal_cutoff=100 --set "lines[0].tension=20100"
                --set analysis.modal_basis=${CMAKE_CURRENT_BINARY_DIR}/app_pw_basis.h5
                -o ${CMAKE_CURRENT_BINARY_DIR}/app_pw_modal_other.h5)
set_tests_properties(app_pantograph_wire_modal_basis_of_another_structure PROPERTIES
                     FIXTURES_REQUIRED pw_modal)
catena_app_test(modal_basis_in_missing_directory_exit_2 2
                "'analysis.modal_basis': cannot use the modal basis '/nonexistent_dir/b.h5': directory /nonexistent_dir does not exist"
                ${app} run meshes/pantograph_wire.yaml --set analysis.structure=modal
                --set analysis.modal_basis=/nonexistent_dir/b.h5
                -o ${CMAKE_CURRENT_BINARY_DIR}/app_pw_modal_missing.h5)
catena_app_test(run_pantograph_wire_modal_np2 0 "modal model: 175 modes"
                ${MPIEXEC_EXECUTABLE} -n 2 --oversubscribe ${app} run meshes/pantograph_wire.yaml
                --set analysis.structure=modal --set analysis.modal_cutoff=100
                -o ${CMAKE_CURRENT_BINARY_DIR}/app_pw_modal_np2.h5)
set_tests_properties(app_run_pantograph_wire_modal_np2 PROPERTIES FIXTURES_SETUP pw_modal_np2)
catena_app_check(pantograph_wire_modal_check "pw_linear;pw_modal;pw_modal_np2"
                 check_modal_structure.py ${CMAKE_CURRENT_BINARY_DIR}/app_pw_linear.h5
                 ${CMAKE_CURRENT_BINARY_DIR}/app_pw_modal.h5 0.01 0.005
                 ${CMAKE_CURRENT_BINARY_DIR}/app_pw_modal_np2.h5)
set(slack_pantograph "pantographs=[{name: leading, path: contact_wire, speed_kmh: 300, start: 40, static_force: 300, model: en50318}]")
catena_app_test(run_slack_droppers_linear 0 "done at t = 1.2 s"
                ${app} run tests/data/app/catenary_pantograph.yaml --set ${slack_pantograph}
                --set analysis.structure=linear --set integrator.dt=0.00025
                --set output.interval=0.001 -o ${CMAKE_CURRENT_BINARY_DIR}/app_slack_linear.h5)
set_tests_properties(app_run_slack_droppers_linear PROPERTIES FIXTURES_SETUP slack_linear)
catena_app_test(run_slack_droppers_modal 0 "27 droppers that may go slack"
                ${app} run tests/data/app/catenary_pantograph.yaml --set ${slack_pantograph}
                --set analysis.structure=modal --set analysis.modal_cutoff=300
                --set integrator.dt=0.00025 --set output.interval=0.001
                -o ${CMAKE_CURRENT_BINARY_DIR}/app_slack_modal.h5)
set_tests_properties(app_run_slack_droppers_modal PROPERTIES FIXTURES_SETUP slack_modal)
catena_app_check(slack_droppers_modal_check "slack_linear;slack_modal"
                 check_modal_structure.py ${CMAKE_CURRENT_BINARY_DIR}/app_slack_linear.h5
                 ${CMAKE_CURRENT_BINARY_DIR}/app_slack_modal.h5 0.03 0.005)
# `catena stats --series steps`: the statistics of every step's contact force. The same
# fixed-step run sampled at every step and at 0.05 s gives the same statistics from its
# steps as the fine run from its samples; the coarse samples are refused (20 Hz cut-off).
catena_app_test(run_pantograph_wire_every_step 0 "done at t = 1.5 s"
                ${app} run meshes/pantograph_wire.yaml --set output.interval=0.0002
                -o ${CMAKE_CURRENT_BINARY_DIR}/app_pw_every_step.h5)
set_tests_properties(app_run_pantograph_wire_every_step PROPERTIES FIXTURES_SETUP pw_every_step)
catena_app_test(run_pantograph_wire_coarse_output 0 "done at t = 1.5 s"
                ${app} run meshes/pantograph_wire.yaml --set output.interval=0.05
                -o ${CMAKE_CURRENT_BINARY_DIR}/app_pw_coarse_output.h5)
set_tests_properties(app_run_pantograph_wire_coarse_output PROPERTIES FIXTURES_SETUP
                     pw_coarse_output)
catena_app_check(stats_series_steps "pw_every_step;pw_coarse_output" check_stats_series.py
                 $<TARGET_FILE:catena> ${CMAKE_CURRENT_BINARY_DIR}/app_pw_every_step.h5
                 ${CMAKE_CURRENT_BINARY_DIR}/app_pw_coarse_output.h5 10 40)
# The same on a catenary: the uplift at the supports from every step's registration heights
# (/steps/registration_height) equals the every-step samples', not the coarse samples'.
catena_app_test(run_catenary_pantograph_every_step 0 "done at t = 1.2 s"
                ${app} run tests/data/app/catenary_pantograph.yaml --set output.interval=0.001
                -o ${CMAKE_CURRENT_BINARY_DIR}/app_cp_every_step.h5)
set_tests_properties(app_run_catenary_pantograph_every_step PROPERTIES FIXTURES_SETUP
                     cp_every_step)
catena_app_test(run_catenary_pantograph_coarse_output 0 "done at t = 1.2 s"
                ${app} run tests/data/app/catenary_pantograph.yaml --set output.interval=0.05
                -o ${CMAKE_CURRENT_BINARY_DIR}/app_cp_coarse_output.h5)
set_tests_properties(app_run_catenary_pantograph_coarse_output PROPERTIES FIXTURES_SETUP
                     cp_coarse_output)
catena_app_check(stats_series_steps_uplift "cp_every_step;cp_coarse_output"
                 check_stats_series.py $<TARGET_FILE:catena>
                 ${CMAKE_CURRENT_BINARY_DIR}/app_cp_every_step.h5
                 ${CMAKE_CURRENT_BINARY_DIR}/app_cp_coarse_output.h5 60 120)
catena_app_check(plot_figures cp_every_step check_plot.py $<TARGET_FILE:catena>
                 ${CMAKE_CURRENT_BINARY_DIR}/app_cp_every_step.h5
                 ${CMAKE_CURRENT_BINARY_DIR}/plot_figures)
set_tests_properties(app_plot_figures PROPERTIES WORKING_DIRECTORY ${CMAKE_SOURCE_DIR}
                     ENVIRONMENT "${mpi_env}")
catena_app_test(stats_unknown_series_exit_2 2 "unknown series 'step'. accepted: samples"
                ${app} stats x.h5 --series step)
# The PETSc TS bridge with BDF at np 2. The scene's integrator map is replaced whole: its
# radau `stages` key is an error for type petsc.
catena_app_test(run_taut_string_petsc_bdf_np2 0 "dynamics: petsc\\(bdf\\)"
                ${MPIEXEC_EXECUTABLE} -n 2 --oversubscribe ${app} run meshes/taut_string.yaml
                --set "integrator={type: petsc, dt: 0.005}" --set analysis.duration=1
                -ts_type bdf -o ${CMAKE_CURRENT_BINARY_DIR}/app_taut_string_petsc.h5)
# Rigid bodies: the heavy top of meshes/heavy_top.yaml in steady precession on 1 and 2 ranks
# (nutation, precession rate and pin force against the closed form, the same on both), and
# what catena check says of it.
catena_app_run_on_1_and_2(heavy_top "done at t = 0.5 s"
                          meshes/heavy_top.yaml --set analysis.duration=0.5)
catena_app_check(heavy_top "heavy_top_run" check_heavy_top.py
                 ${CMAKE_CURRENT_BINARY_DIR}/app_heavy_top.h5
                 ${CMAKE_CURRENT_BINARY_DIR}/app_heavy_top_np2.h5)
# The same top by Adams-Bashforth-Moulton (explicit; the body frame's nonlinear constraints
# kept by projection) at 0.2 ms for 0.5 s: second order (nutation 2.9e-5 rad, energy 1.6e-4;
# at 0.1 ms 7.1e-6 and 3.6e-5).
catena_app_test(run_heavy_top_abm 0 "done at t = 0.5 s: 2500 steps"
                ${app} run meshes/heavy_top.yaml --set analysis.duration=0.5
                --set "integrator={type: abm, order: 2, dt: 2.0e-4}"
                -o ${CMAKE_CURRENT_BINARY_DIR}/app_heavy_top_abm.h5)
set_tests_properties(app_run_heavy_top_abm PROPERTIES FIXTURES_SETUP heavy_top_abm_run)
catena_app_check(heavy_top_abm "heavy_top_abm_run" check_heavy_top.py
                 ${CMAKE_CURRENT_BINARY_DIR}/app_heavy_top_abm.h5 --nutation 6e-5
                 --precession-rtol 2e-4 --energy 3e-4 --momentum 2e-4 --omega-z 1e-2)
# The same top by RATTLE at 1 ms for 2 s, on 1 and 2 ranks: second order in the angles
# (9e-5 rad measured), the energy within 1e-8 (1.5e-9) and L_z within 1e-11 (8e-13) as a
# symplectic method keeps them; a step beyond its stability limit is refused.
set(rattle_top --set "integrator={type: rattle, dt: 0.001}")
catena_app_run_on_1_and_2(heavy_top_rattle "done at t = 2 s" meshes/heavy_top.yaml ${rattle_top})
catena_app_check(heavy_top_rattle "heavy_top_rattle_run" check_heavy_top.py
                 ${CMAKE_CURRENT_BINARY_DIR}/app_heavy_top_rattle.h5
                 ${CMAKE_CURRENT_BINARY_DIR}/app_heavy_top_rattle_np2.h5 --nutation 2e-4
                 --precession-rtol 2e-4 --energy 1e-8 --momentum 1e-11 --omega-z 1e-2)
catena_app_test(run_heavy_top_rattle_step_too_long_exit_2 2
                "RATTLE is explicit in the stiffness, stable for steps up to 2/omega_max = 0\\.0331"
                ${app} run meshes/heavy_top.yaml --set "integrator={type: rattle, dt: 0.05}"
                -o ${CMAKE_CURRENT_BINARY_DIR}/app_heavy_top_rattle_too_long.h5)
catena_app_test(check_heavy_top 0 "rigid body 'top' +node 1, mass 1 kg"
                ${app} check meshes/heavy_top.yaml)
