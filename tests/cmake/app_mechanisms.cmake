# Mechanisms and couplings: joints, rigid bodies, nearly slack and absorbing ends, moving
# windows, projected velocities, sliders, bilateral contact, the arm pantograph, constraints.
# Included by tests/CMakeLists.txt, whose helpers (catena_app_test, catena_app_check) and
# variables (app, expect, mpi_env) it uses.

# Joints: the slider-crank of meshes/slider_crank.yaml on 1 and 2 ranks (the slider's
# position against the crank angle, the kinetic energy, the same on both).
catena_app_run_on_1_and_2(slider_crank "done at t = 0.5 s"
                          meshes/slider_crank.yaml --set analysis.duration=0.5)
catena_app_check(slider_crank "slider_crank_run" check_slider_crank.py
                 ${CMAKE_CURRENT_BINARY_DIR}/app_slider_crank.h5
                 ${CMAKE_CURRENT_BINARY_DIR}/app_slider_crank_np2.h5)
catena_app_test(check_slider_crank 0 "joint 'crank pin' +spherical between body 'rod' and body 'crank'"
                ${app} check meshes/slider_crank.yaml)
# Surfaces: a point mass bouncing on a floor and sliding on it with Coulomb friction, against
# closed forms (tests/app/check_surface_contact.py).
catena_app_test(run_surface_bounce 0 "done at t = 0.25 s"
                ${app} run tests/data/app/surface_bounce.yaml
                -o ${CMAKE_CURRENT_BINARY_DIR}/app_surface_bounce.h5)
catena_app_test(run_surface_friction 0 "done at t = 0.8 s"
                ${app} run tests/data/app/surface_friction.yaml
                -o ${CMAKE_CURRENT_BINARY_DIR}/app_surface_friction.h5)
set_tests_properties(app_run_surface_bounce app_run_surface_friction PROPERTIES
                     FIXTURES_SETUP surface_runs)
catena_app_check(surface_contact "surface_runs" check_surface_contact.py
                 ${CMAKE_CURRENT_BINARY_DIR}/app_surface_bounce.h5
                 ${CMAKE_CURRENT_BINARY_DIR}/app_surface_friction.h5)
# A surface's force at a node with a fixed component counts once in the reactions.
catena_app_test(static_surface_on_held_node 0 "sum of support reactions: \\[19.62, 0, 0\\] N"
                ${app} run tests/data/app/surface_held_component.yaml
                -o ${CMAKE_CURRENT_BINARY_DIR}/app_surface_held.h5)
catena_app_test(check_surface 0 "surface 'floor' +plane through \\(0, 0, -0.01\\) m, normal \\(0, 0, 1\\), 1 node may touch it"
                ${app} check tests/data/app/surface_friction.yaml)
# Absorbing ends: a driven wire whose waves leave through its cut end (transverse and axial),
# against the same wire pinned there, on 1 and 2 ranks (tests/app/check_absorbing_end.py).
set(absorbing_scene tests/data/app/absorbing_end_string.yaml)
catena_app_test(run_absorbing_end 0 "absorbing ends: 1 line ends pulled by their force"
                ${app} run ${absorbing_scene} -o ${CMAKE_CURRENT_BINARY_DIR}/app_absorbing.h5)
catena_app_test(run_absorbing_end_np2 0 "done at t = 2 s"
                ${MPIEXEC_EXECUTABLE} -n 2 --oversubscribe ${app} run ${absorbing_scene}
                -o ${CMAKE_CURRENT_BINARY_DIR}/app_absorbing_np2.h5)
catena_app_test(run_absorbing_end_pinned 0 "done at t = 2 s"
                ${app} run ${absorbing_scene} --set "absorbing_ends=[]"
                --set "supports=[{node: 2, fix: pinned}]"
                -o ${CMAKE_CURRENT_BINARY_DIR}/app_absorbing_pinned.h5)
catena_app_test(run_absorbing_end_axial 0 "done at t = 0.08 s"
                ${app} run ${absorbing_scene}
                --set "constraints=[{type: prescribed, node: 1, amplitude: [1.0e-4, 0, 0], frequency: 200}]"
                --set analysis.duration=0.08 --set integrator.dt=2.0e-5
                --set output.interval=1.0e-4 -o ${CMAKE_CURRENT_BINARY_DIR}/app_absorbing_axial.h5)
set(restarted ${CMAKE_CURRENT_BINARY_DIR}/app_absorbing_restarted.h5)
catena_app_test(run_absorbing_end_restarted 0 "restart: from .* at t = 1 s"
                sh -c "${app} run ${absorbing_scene} --set analysis.duration=1 -o ${restarted} && ${app} run ${absorbing_scene} --restart -o ${restarted}")
set_tests_properties(app_run_absorbing_end app_run_absorbing_end_np2 app_run_absorbing_end_pinned
                     app_run_absorbing_end_axial app_run_absorbing_end_restarted
                     PROPERTIES FIXTURES_SETUP absorbing_runs)
# Nearly slack: 1 N on EA 1.8e7 N (strain 5.6e-8, below the 1e-7 an end needs).
catena_app_test(run_absorbing_end_slack_line_exit_3 3
                "absorbing end at node 2: its line is not taut there"
                ${app} run ${absorbing_scene}
                --set "lines=[{name: wire, from: 1, to: 2, elements: 60, section: wire, tension: 1}]"
                -o ${CMAKE_CURRENT_BINARY_DIR}/app_absorbing_slack.h5)
catena_app_test(check_absorbing_end 0 "absorbing ends +1 \\(held in statics"
                ${app} check ${absorbing_scene})
catena_app_test(modes_absorbing_end_exit_2 2 "modes of a scene with absorbing ends are not computed"
                ${app} modes ${absorbing_scene} --set "constraints=[]"
                --set "supports=[{node: 1, fix: pinned}]"
                -o ${CMAKE_CURRENT_BINARY_DIR}/app_absorbing_modes.h5)
# A catenary cut from a longer line (catenary.ends: absorbing): its four wire ends become
# absorbing ends after shape finding; the same motion on 2 ranks; the refusals.
set(cut_catenary tests/data/app/catenary_pantograph.yaml --set catenary.ends=absorbing)
catena_app_test(run_catenary_absorbing_ends 0
                "catenary: the wires' 4 end supports become absorbing ends for the run"
                ${app} run ${cut_catenary} --set analysis.duration=0.1
                -o ${CMAKE_CURRENT_BINARY_DIR}/app_cut_catenary.h5)
catena_app_test(run_catenary_absorbing_ends_np2 0 "absorbing ends: 4 line ends"
                ${MPIEXEC_EXECUTABLE} -n 2 --oversubscribe ${app} run ${cut_catenary}
                --set analysis.duration=0.1 -o ${CMAKE_CURRENT_BINARY_DIR}/app_cut_catenary_np2.h5)
set_tests_properties(app_run_catenary_absorbing_ends app_run_catenary_absorbing_ends_np2
                     PROPERTIES FIXTURES_SETUP absorbing_runs)
catena_app_check(absorbing_end "absorbing_runs" check_absorbing_end.py
                 ${CMAKE_CURRENT_BINARY_DIR}/app_absorbing.h5
                 ${CMAKE_CURRENT_BINARY_DIR}/app_absorbing_pinned.h5
                 ${CMAKE_CURRENT_BINARY_DIR}/app_absorbing_axial.h5
                 ${CMAKE_CURRENT_BINARY_DIR}/app_absorbing_np2.h5 ${restarted}
                 ${CMAKE_CURRENT_BINARY_DIR}/app_cut_catenary.h5
                 ${CMAKE_CURRENT_BINARY_DIR}/app_cut_catenary_np2.h5)
catena_app_test(check_catenary_absorbing_ends 0 "ends +absorbing: both wires pinned"
                ${app} check ${cut_catenary})
catena_app_test(catenary_ends_unknown_exit_2 2 "'catenary.ends': unknown ends 'open'"
                ${app} check tests/data/app/catenary_pantograph.yaml --set catenary.ends=open)
catena_app_test(modes_catenary_absorbing_ends_exit_2 2
                "modes of a scene with absorbing ends are not computed"
                ${app} modes ${cut_catenary} -o ${CMAKE_CURRENT_BINARY_DIR}/app_cut_modes.h5)
catena_app_test(catenary_absorbing_ends_modal_exit_2 2
                "a modal structure with absorbing ends is not available"
                ${app} check ${cut_catenary} --set analysis.structure=modal)
# A moving window (catenary.window): six spans of a 14-span line follow the pantograph,
# against the whole line with absorbing ends; on 2 ranks; stopped after its first move and
# continued with --restart; a staggered 3D window moves two spans at a time
# (tests/app/check_window.py).
set(window_line tests/data/app/catenary_pantograph.yaml --set catenary.spans=14
    --set "pantographs[0].start=174.96" --set "catenary.evaluation_spans=[4, 4]")
set(window_scene ${window_line} --set catenary.window.spans=6)
catena_app_test(run_window 0 "window: moved 1 span along the line at t = 0.06"
                ${app} run ${window_scene} -o ${CMAKE_CURRENT_BINARY_DIR}/app_window.h5)
catena_app_test(run_window_np2 0 "done at t = 1.2 s"
                ${MPIEXEC_EXECUTABLE} -n 2 --oversubscribe ${app} run ${window_scene}
                -o ${CMAKE_CURRENT_BINARY_DIR}/app_window_np2.h5)
catena_app_test(run_window_whole_line 0 "done at t = 1.2 s"
                ${app} run ${window_line} --set catenary.ends=absorbing
                -o ${CMAKE_CURRENT_BINARY_DIR}/app_window_line.h5)
set(window_restarted ${CMAKE_CURRENT_BINARY_DIR}/app_window_restarted.h5)
set(window_sh "tests/data/app/catenary_pantograph.yaml --set catenary.spans=14 --set 'pantographs[0].start=174.96' --set 'catenary.evaluation_spans=[4, 4]' --set catenary.window.spans=6")
catena_app_test(run_window_restarted 0 "restart: from .* at t = 0.5 s"
                sh -c "${app} run ${window_sh} --set analysis.duration=0.5 -o ${window_restarted} && ${app} run ${window_sh} --restart -o ${window_restarted}")
catena_app_test(run_window_staggered 0 "window: moved 2 spans along the line"
                ${app} run ${window_scene} --set catenary.dimension=3 --set catenary.stagger=0.2
                --set catenary.window.spans=7 --set "pantographs[0].start=230"
                --set analysis.duration=0.3
                -o ${CMAKE_CURRENT_BINARY_DIR}/app_window_staggered.h5)
set_tests_properties(app_run_window app_run_window_np2 app_run_window_whole_line
                     app_run_window_restarted PROPERTIES FIXTURES_SETUP window_runs)
catena_app_check(window "window_runs" check_window.py ${CMAKE_CURRENT_BINARY_DIR}/app_window.h5
                 ${CMAKE_CURRENT_BINARY_DIR}/app_window_line.h5
                 ${CMAKE_CURRENT_BINARY_DIR}/app_window_np2.h5 ${window_restarted} ${app})
# In 3D without stagger and with fixed messenger supports, a window end's image holds
# components the end leaves free (the registration's y, the support's z): on 2 ranks too.
catena_app_test(run_window_3d_fixed_supports_np2 0 "window: moved 1 span along the line"
                ${MPIEXEC_EXECUTABLE} -n 2 --oversubscribe ${app} run ${window_scene}
                --set catenary.dimension=3 --set "catenary.messenger_supports={fixed: true}"
                --set analysis.duration=0.1
                -o ${CMAKE_CURRENT_BINARY_DIR}/app_window_3d_fixed.h5)
# The shipped 50 km line in a window of eight spans: it reads and starts.
catena_app_test(check_long_line_window 0 "window +8 spans of a line of 834 spans"
                ${app} check meshes/long_line_window.yaml)
catena_app_test(run_long_line_window 0 "done at t = 0.02 s" ${app} run meshes/long_line_window.yaml
                --set analysis.duration=0.02 -o ${CMAKE_CURRENT_BINARY_DIR}/app_long_line_window.h5)
catena_app_test(check_window 0 "window +6 spans of a line of 14 spans"
                ${app} check ${window_scene})
# The two-arm crane (meshes/two_arm_crane.yaml: bodies, servos, hinge friction, a flexible
# pipe, ground contact), its first 0.6 s with HHT on 1 and 2 ranks: the joints hold, the
# ground pushes by its law, the runs agree (tests/app/check_crane.py).
foreach(np 1 2)
  set(launcher ${app})
  if(np EQUAL 2)
    set(launcher ${MPIEXEC_EXECUTABLE} -n 2 --oversubscribe ${app})
  endif()
  catena_app_test(run_crane_np${np} 0 "done at t = 0.6 s"
                  ${launcher} run meshes/two_arm_crane.yaml --set analysis.duration=0.6
                  --set "integrator={type: hht, dt: 1.0e-3}"
                  -o ${CMAKE_CURRENT_BINARY_DIR}/app_crane_np${np}.h5)
endforeach()
set_tests_properties(app_run_crane_np1 app_run_crane_np2 PROPERTIES FIXTURES_SETUP crane_runs)
catena_app_check(crane "crane_runs" check_crane.py ${CMAKE_CURRENT_BINARY_DIR}/app_crane_np1.h5
                 ${CMAKE_CURRENT_BINARY_DIR}/app_crane_np2.h5)
# A joint's dry friction, position servo and torque limit against closed forms
# (tests/data/app/joint_servo_friction.yaml), on 1 and 2 ranks.
catena_app_run_on_1_and_2(joint_servo "done at t = 0.4 s" tests/data/app/joint_servo_friction.yaml)
catena_app_check(joint_servo "joint_servo_run" check_joint_servo.py
                 ${CMAKE_CURRENT_BINARY_DIR}/app_joint_servo.h5
                 ${CMAKE_CURRENT_BINARY_DIR}/app_joint_servo_np2.h5)
catena_app_test(check_joint_servo 0
                "joint 'limited hinge' .*spring 1000 N\\*m/rad about 1 rad, limited to 2 N\\*m"
                ${app} check tests/data/app/joint_servo_friction.yaml)
# Velocities the joints do not allow are projected, and the run says so.
catena_app_test(run_slider_crank_projects_velocity 0 "initial velocity: projected onto the constraints"
                ${app} run meshes/slider_crank.yaml --set analysis.duration=0.01
                --set "bodies[1].angular_velocity=[0, 0, 0]"
                -o ${CMAKE_CURRENT_BINARY_DIR}/app_slider_crank_projected.h5)
# HHT's Newton matrix with multipliers is factored by PETSc's LU with the multipliers last
# (its default on one rank; named here as well); the slider-crank's pivots then never
# vanish and no note of a fall-back to MUMPS is printed. An IRK stage block with
# multipliers still needs a pivoting package: PETSc's LU forced on it is refused naming
# the option (its zero pivots used to halve every step down to dt_min).
catena_app_test(run_joints_petsc_lu 0 "done at t = 0.01 s: 10 steps \\(0 rejected"
                ${app} run meshes/slider_crank.yaml --set analysis.duration=0.01
                --set "integrator={type: hht, alpha: -0.1, dt: 1.0e-3}"
                -o ${CMAKE_CURRENT_BINARY_DIR}/app_joints_petsc_lu.h5
                -hht_pc_factor_mat_solver_type petsc)
set_tests_properties(app_run_joints_petsc_lu PROPERTIES FAIL_REGULAR_EXPRESSION
                     "met a zero pivot")
catena_app_test(run_joints_petsc_lu_irk_block_exit_2 2
                "-irk_block0_pc_factor_mat_solver_type.*does not pivot"
                ${app} run meshes/squeezer.yaml --set analysis.duration=0.001
                -o ${CMAKE_CURRENT_BINARY_DIR}/app_joints_petsc_lu_irk.h5
                -irk_block0_pc_factor_mat_solver_type PETSc)
# Andrews' squeezer (meshes/squeezer.yaml): seven bodies, ten joints, against the published
# reference solution at t = 0.03 s (positions to 1e-8 relative at the scene's 10 us step:
# 8e-10 measured) and its energy balance, on 1 and 2 ranks.
catena_app_run_on_1_and_2(squeezer "done at t = 0.03 s" meshes/squeezer.yaml)
catena_app_check(squeezer "squeezer_run" check_squeezer.py
                 ${CMAKE_CURRENT_BINARY_DIR}/app_squeezer.h5 --position-rtol 1e-8
                 --velocity-rtol 1e-4 --energy 1e-8
                 --other ${CMAKE_CURRENT_BINARY_DIR}/app_squeezer_np2.h5)
# The issue's target for the error-controlled methods: Radau IIA at rtol 1e-6 (step doubling,
# the velocities' error estimated too) puts the angles within 1e-6 of the reference (1.7e-8
# measured; 1.4e-6 when only the positions were estimated).
catena_app_test(run_squeezer_adaptive 0 "done at t = 0.03 s"
                ${app} run meshes/squeezer.yaml --set
                "integrator={type: radau_iia, stages: 3, dt: 1e-6, adaptive: true, rtol: 1e-6, atol: 1e-8}"
                -o ${CMAKE_CURRENT_BINARY_DIR}/app_squeezer_adaptive.h5)
set_tests_properties(app_run_squeezer_adaptive PROPERTIES FIXTURES_SETUP squeezer_adaptive_run)
catena_app_check(squeezer_adaptive "squeezer_adaptive_run" check_squeezer.py
                 ${CMAKE_CURRENT_BINARY_DIR}/app_squeezer_adaptive.h5 --position-rtol 1e-6
                 --velocity-rtol 1e-3 --energy 1e-6)
# Adams–Bashforth–Moulton on the squeezer's nonlinear constraints, with the seed paper's
# stabilisation (positions and velocities projected onto them at each step), on 2 ranks: at
# 40 us the angles 1.6e-3 from the reference, the energy balance 1.2e-3 (order 2: 3.2e-4
# and 2.5e-4 at 20 us, the same on 1 rank to 3e-13 rad; docs/validation.md).
catena_app_test(run_squeezer_abm_np2 0 "done at t = 0.03 s: 750 steps"
                ${MPIEXEC_EXECUTABLE} -n 2 --oversubscribe ${app} run meshes/squeezer.yaml
                --set "integrator={type: abm, order: 2, dt: 4e-5}"
                -o ${CMAKE_CURRENT_BINARY_DIR}/app_squeezer_abm_np2.h5)
set_tests_properties(app_run_squeezer_abm_np2 PROPERTIES FIXTURES_SETUP squeezer_abm_run)
catena_app_check(squeezer_abm "squeezer_abm_run" check_squeezer.py
                 ${CMAKE_CURRENT_BINARY_DIR}/app_squeezer_abm_np2.h5 --position-rtol 3e-3
                 --velocity-rtol 0.4 --energy 3e-3)
catena_app_test(check_squeezer 0 "joint 'E on body 6' +spherical between body 'body2' and body 'body6'"
                ${app} check meshes/squeezer.yaml)
# Sliders: the trolley of meshes/trolley.yaml on a messenger wire on 1, 2 and 3 ranks (on the
# wire's curve, the friction law, the same on both), and a trolley run off its wire's end.
catena_app_test(run_trolley 0 "each slider held at its start, released at t = 0"
                ${app} run meshes/trolley.yaml --set analysis.duration=5
                -o ${CMAKE_CURRENT_BINARY_DIR}/app_trolley.h5)
catena_app_test(run_trolley_np2 0 "done at t = 5 s"
                ${MPIEXEC_EXECUTABLE} -n 2 --oversubscribe ${app} run meshes/trolley.yaml
                --set analysis.duration=5 -o ${CMAKE_CURRENT_BINARY_DIR}/app_trolley_np2.h5)
catena_app_test(run_trolley_np3 0 "done at t = 5 s"
                ${MPIEXEC_EXECUTABLE} -n 3 --oversubscribe ${app} run meshes/trolley.yaml
                --set analysis.duration=5 -o ${CMAKE_CURRENT_BINARY_DIR}/app_trolley_np3.h5)
set_tests_properties(app_run_trolley app_run_trolley_np2 app_run_trolley_np3 PROPERTIES
                     FIXTURES_SETUP trolley_run)
catena_app_check(trolley "trolley_run" check_trolley.py
                 ${CMAKE_CURRENT_BINARY_DIR}/app_trolley.h5
                 ${CMAKE_CURRENT_BINARY_DIR}/app_trolley_np2.h5
                 ${CMAKE_CURRENT_BINARY_DIR}/app_trolley_np3.h5)
# Coulomb friction on a slider: a bead on a rigid wire inclined at 30 degrees slides (mu
# 0.3, HHT on 1 and 2 ranks, Radau IIA) at g (sin 30 - mu cos 30) and sticks (mu 0.8),
# creeping at the regularised law's speed (tests/app/check_bead_friction.py). Newton keeps
# its tangent (a few factorisations in 500 steps) only if the friction's derivative in the
# multipliers is in its matrix: without it, 300.
set(bead ${CMAKE_CURRENT_SOURCE_DIR}/data/app/bead_on_incline.yaml)
catena_app_test(run_bead_slides 0 "done at t = 0.5 s: 500 steps \\(0 rejected.* [1-9] factorisations"
                ${app} run ${bead} -o ${CMAKE_CURRENT_BINARY_DIR}/app_bead_slides.h5)
catena_app_test(run_bead_slides_np2 0 "done at t = 0.5 s"
                ${MPIEXEC_EXECUTABLE} -n 2 --oversubscribe ${app} run ${bead}
                -o ${CMAKE_CURRENT_BINARY_DIR}/app_bead_slides_np2.h5)
catena_app_test(run_bead_slides_radau 0 "done at t = 0.5 s"
                ${app} run ${bead} --set "integrator={type: radau, stages: 3, dt: 1e-3}"
                -o ${CMAKE_CURRENT_BINARY_DIR}/app_bead_slides_radau.h5)
catena_app_test(run_bead_sticks 0 "done at t = 0.5 s: 500 steps \\(0 rejected.* [1-9] factorisations"
                ${app} run ${bead} --set "sliders[0].friction=0.8"
                --set "sliders[0].stick_speed=1e-3"
                -o ${CMAKE_CURRENT_BINARY_DIR}/app_bead_sticks.h5)
set_tests_properties(app_run_bead_slides app_run_bead_slides_np2 app_run_bead_slides_radau
                     app_run_bead_sticks PROPERTIES FIXTURES_SETUP bead_runs)
foreach(run slides slides_np2 slides_radau)
  catena_app_check(bead_${run}_check "bead_runs" check_bead_friction.py
                   ${CMAKE_CURRENT_BINARY_DIR}/app_bead_${run}.h5 0.3 1e-4 slide)
endforeach()
catena_app_check(bead_sticks_check "bead_runs" check_bead_friction.py
                 ${CMAKE_CURRENT_BINARY_DIR}/app_bead_sticks.h5 0.8 1e-3 stick)
catena_app_test(check_bead_friction 0 "Coulomb friction 0.3 \\(stick speed 0.0001 m/s\\)"
                ${app} check ${bead})
# Support reactions with a slider next to a middle support (not among its path's first
# nodes): force and moment balance at the static start, on 2 ranks.
catena_app_test(run_trolley_mid_support_np2 0 "done at t = 0.01 s"
                ${MPIEXEC_EXECUTABLE} -n 2 --oversubscribe ${app} run
                ${CMAKE_CURRENT_SOURCE_DIR}/data/app/trolley_mid_support.yaml
                -o ${CMAKE_CURRENT_BINARY_DIR}/app_trolley_mid_support.h5)
set_tests_properties(app_run_trolley_mid_support_np2 PROPERTIES FIXTURES_SETUP trolley_mid)
catena_app_check(trolley_mid_support_reactions "trolley_mid" check_slider_reactions.py
                 ${CMAKE_CURRENT_BINARY_DIR}/app_trolley_mid_support.h5)
# The trolley on a refined wire (320 elements on one rank, 1280 on two): the slider acts on
# the element under it, so its path may be long; its travel converges at second order.
catena_app_test(run_trolley_320 0 "done at t = 2 s"
                ${app} run meshes/trolley.yaml --set "lines[0].elements=320"
                --set analysis.duration=2 -o ${CMAKE_CURRENT_BINARY_DIR}/app_trolley_320.h5)
catena_app_test(run_trolley_1280_np2 0 "done at t = 2 s"
                ${MPIEXEC_EXECUTABLE} -n 2 --oversubscribe ${app} run meshes/trolley.yaml
                --set "lines[0].elements=1280" --set analysis.duration=2
                -o ${CMAKE_CURRENT_BINARY_DIR}/app_trolley_1280.h5)
set_tests_properties(app_run_trolley_320 app_run_trolley_1280_np2 PROPERTIES
                     FIXTURES_SETUP trolley_refined)
catena_app_check(trolley_refinement "trolley_run;trolley_refined" check_slider_refinement.py
                 ${CMAKE_CURRENT_BINARY_DIR}/app_trolley.h5
                 ${CMAKE_CURRENT_BINARY_DIR}/app_trolley_320.h5
                 ${CMAKE_CURRENT_BINARY_DIR}/app_trolley_1280.h5)
catena_app_test(check_trolley 0 "slider 'trolley' +node 3 along 'wire' \\(80 elements, 40 m\\), from 10 m"
                ${app} check meshes/trolley.yaml)
catena_app_test(run_trolley_leaves_path 3 "slider 'trolley' left its path 'wire' at t = 1.0"
                ${app} run meshes/trolley.yaml --set analysis.duration=3
                --set "gravity=[-20, 0, -9.81]"
                -o ${CMAKE_CURRENT_BINARY_DIR}/app_trolley_leaves.h5)
# Bilateral pantograph contact on meshes/pantograph_wire.yaml against the penalty contact,
# on 1 and 2 ranks (the head on the wire, the same mean force, never zero).
foreach(kind bilateral penalty)
  catena_app_test(run_pantograph_wire_${kind} 0 "done at t = 0.6 s"
                  ${app} run meshes/pantograph_wire.yaml --set analysis.duration=0.6
                  --set "pantographs[0].contact={type: ${kind}}"
                  -o ${CMAKE_CURRENT_BINARY_DIR}/app_pantograph_wire_${kind}.h5)
endforeach()
catena_app_test(run_pantograph_wire_bilateral_np2 0 "done at t = 0.6 s"
                ${MPIEXEC_EXECUTABLE} -n 2 --oversubscribe ${app} run meshes/pantograph_wire.yaml
                --set analysis.duration=0.6 --set "pantographs[0].contact={type: bilateral}"
                -o ${CMAKE_CURRENT_BINARY_DIR}/app_pantograph_wire_bilateral_np2.h5)
set_tests_properties(app_run_pantograph_wire_bilateral app_run_pantograph_wire_penalty
                     app_run_pantograph_wire_bilateral_np2 PROPERTIES
                     FIXTURES_SETUP bilateral_contact_run)
catena_app_test(check_pantograph_wire_bilateral 0 "contact bilateral: a multiplier holds the head"
                ${app} check meshes/pantograph_wire.yaml
                --set "pantographs[0].contact={type: bilateral}")
catena_app_check(bilateral_contact "bilateral_contact_run" check_bilateral_contact.py
                 ${CMAKE_CURRENT_BINARY_DIR}/app_pantograph_wire_bilateral.h5
                 ${CMAKE_CURRENT_BINARY_DIR}/app_pantograph_wire_penalty.h5
                 ${CMAKE_CURRENT_BINARY_DIR}/app_pantograph_wire_bilateral_np2.h5)
# The single-arm pantograph (model: arm_en50318, two rigid bodies) on the same wire, on 1
# and 2 ranks: its static start against the mechanism's closed-form moment balance, its
# contact force against the lumped model's (the penalty run above) and across ranks.
catena_app_test(run_pantograph_wire_arm 0 "done at t = 0.6 s"
                ${app} run meshes/pantograph_wire.yaml --set analysis.duration=0.6
                --set "pantographs[0].model=arm_en50318"
                -o ${CMAKE_CURRENT_BINARY_DIR}/app_pantograph_wire_arm.h5)
catena_app_test(run_pantograph_wire_arm_np2 0 "done at t = 0.6 s"
                ${MPIEXEC_EXECUTABLE} -n 2 --oversubscribe ${app} run meshes/pantograph_wire.yaml
                --set analysis.duration=0.6 --set "pantographs[0].model=arm_en50318"
                -o ${CMAKE_CURRENT_BINARY_DIR}/app_pantograph_wire_arm_np2.h5)
set_tests_properties(app_run_pantograph_wire_arm app_run_pantograph_wire_arm_np2 PROPERTIES
                     FIXTURES_SETUP arm_pantograph_run)
catena_app_check(arm_pantograph "arm_pantograph_run;bilateral_contact_run"
                 check_arm_pantograph.py
                 ${CMAKE_CURRENT_BINARY_DIR}/app_pantograph_wire_arm.h5
                 ${CMAKE_CURRENT_BINARY_DIR}/app_pantograph_wire_penalty.h5
                 ${CMAKE_CURRENT_BINARY_DIR}/app_pantograph_wire_arm_np2.h5)
catena_app_test(check_pantograph_wire_arm 0
                "equivalent stages there \\(head first\\): 7\\.2 kg, 4200 N/m, 10 N\\*s/m. 15 kg, 50 N/m and 90 N\\*s/m to ground"
                ${app} check meshes/pantograph_wire.yaml --set "pantographs[0].model=arm_en50318")
# Lagrange-multiplier constraints: the driven pendulum (a prescribed pivot) with HHT and
# Radau IIA at np 2.
foreach(type hht radau)
  catena_app_test(run_driven_pendulum_${type}_np2 0 "done at t = 0.2 s"
                  ${MPIEXEC_EXECUTABLE} -n 2 --oversubscribe ${app} run meshes/driven_pendulum.yaml
                  --set integrator.type=${type} --set analysis.duration=0.2
                  -o ${CMAKE_CURRENT_BINARY_DIR}/app_driven_pendulum_${type}.h5)
endforeach()
# The pivot force (the multiplier, /samples/constraint_forces) against Newton's second law
# for the whole rope, m (r_c'' - g), from the sampled positions and slopes.
catena_app_test(run_driven_pendulum_fine_np2 0 "done at t = 0.5 s"
                ${MPIEXEC_EXECUTABLE} -n 2 --oversubscribe ${app} run meshes/driven_pendulum.yaml
                --set integrator.type=radau --set analysis.duration=0.5
                --set output.interval=0.0005 --set integrator.dt=0.0005
                -o ${CMAKE_CURRENT_BINARY_DIR}/app_driven_pendulum_fine.h5)
set_tests_properties(app_run_driven_pendulum_fine_np2 PROPERTIES FIXTURES_SETUP driven_fine)
catena_app_check(driven_pendulum_pivot_force "driven_fine" check_pivot_force.py
                 ${CMAKE_CURRENT_BINARY_DIR}/app_driven_pendulum_fine.h5 9.972 0.01)
catena_app_test(petsc_refuses_constraints 2 "integrator type 'petsc' takes no Lagrange-multiplier"
                ${app} run meshes/driven_pendulum.yaml --set "integrator={type: petsc}"
                -o ${CMAKE_CURRENT_BINARY_DIR}/app_driven_pendulum_petsc.h5)
# Checkpoints: SIGTERM part-way, --restart on another rank count, same results as an
# uninterrupted run; a finished run with constraints extended by --restart. Long (it runs
# alone for 35-130 s): app_restart_exact_core covers restarts on another rank count and
# app_launcher_loss the SIGTERM exit, both in the default run.
add_test(NAME app_restart_roundtrip
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/app/restart_roundtrip.sh ${app}
                 ${MPIEXEC_EXECUTABLE} ${CMAKE_CURRENT_BINARY_DIR}
         WORKING_DIRECTORY ${CMAKE_SOURCE_DIR})
set_tests_properties(app_restart_roundtrip PROPERTIES LABELS "app;long" ENVIRONMENT "${mpi_env}"
                     TIMEOUT 900 RUN_SERIAL TRUE)
# A damaged checkpoint (a number that is not one, a dataset missing) is refused, exit 2.
add_test(NAME app_restart_damaged
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/app/restart_damaged.sh ${app}
                 ${CMAKE_CURRENT_BINARY_DIR}
         WORKING_DIRECTORY ${CMAKE_SOURCE_DIR})
set_tests_properties(app_restart_damaged PROPERTIES LABELS app ENVIRONMENT "${mpi_env}"
                     TIMEOUT 300)
# Parallel HDF5's metadata sync points in nearly every write (CATENA_HDF5_SYNC_BYTES=512),
# on 3 ranks of a line whose middle rank has no support (empty reaction rows) and with
# checkpoints: every rank must meet them in the same calls, or the run hangs (until
# the timeout). The writer that let rank 0 alone write the time and contact rows hung
# here at 512 and 1024 bytes (a 2-rank EN 50318 run once hung so at the default 256 KiB;
# docs/architecture.md, "HDF5 rows are redistributed").
catena_app_test(hdf5_sync_points_np3 0 "done at t = 0.3 s"
                ${MPIEXEC_EXECUTABLE} -n 3 --oversubscribe -x CATENA_HDF5_SYNC_BYTES=512 ${app}
                run meshes/pantograph_wire.yaml --set analysis.duration=0.3
                --set output.checkpoint_wall_seconds=0.2
                -o ${CMAKE_CURRENT_BINARY_DIR}/app_hdf5_sync_points.h5)
set_tests_properties(app_hdf5_sync_points_np3 PROPERTIES TIMEOUT 120)
catena_app_test(hdf5_sync_bytes_out_of_range_exit_2 2
                "CATENA_HDF5_SYNC_BYTES=12: accepted: a whole number of bytes, 512 to 33554432"
                env CATENA_HDF5_SYNC_BYTES=12 ${app} run meshes/taut_string.yaml --quiet
                -o ${CMAKE_CURRENT_BINARY_DIR}/app_hdf5_sync_bytes.h5)
# LD_PRELOAD fault injection: one rank's MPI_Wtime shifted (support/preload/wtime_skew.c).
add_library(catena_wtime_skew MODULE ${CMAKE_CURRENT_SOURCE_DIR}/support/preload/wtime_skew.c)
target_link_libraries(catena_wtime_skew PRIVATE MPI::MPI_C)
add_test(NAME app_clock_skew
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/app/clock_skew.sh ${app} ${MPIEXEC_EXECUTABLE}
                 $<TARGET_FILE:catena_wtime_skew> ${CMAKE_CURRENT_BINARY_DIR}
         WORKING_DIRECTORY ${CMAKE_SOURCE_DIR})
set_tests_properties(app_clock_skew PROPERTIES LABELS app ENVIRONMENT "${mpi_env}"
                     TIMEOUT 600 PROCESSORS 2)
add_test(NAME app_run_files
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/app/run_files.sh ${app} ${CMAKE_CURRENT_BINARY_DIR}
         WORKING_DIRECTORY ${CMAKE_SOURCE_DIR})
set_tests_properties(app_run_files PROPERTIES LABELS app TIMEOUT 600)
add_test(NAME app_launcher_loss
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/app/launcher_loss.sh ${app} ${MPIEXEC_EXECUTABLE}
                 ${CMAKE_CURRENT_BINARY_DIR}
         WORKING_DIRECTORY ${CMAKE_SOURCE_DIR})
set_tests_properties(app_launcher_loss PROPERTIES LABELS app ENVIRONMENT "${mpi_env}"
                     TIMEOUT 600 PROCESSORS 2)
