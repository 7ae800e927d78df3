# The installed package, the extremes suite, the error bar, catena study and sweep, the
# scaling study.
# Included by tests/CMakeLists.txt, whose helpers (catena_app_test, catena_app_check) and
# variables (app, expect, mpi_env) it uses.

# The installed package (tests/install/install_consumer.sh): `cmake --install` of this
# build into a directory of its own, the installed catena and plot scripts, and the example
# consumer (tests/install/consumer) configured with find_package(Catena), built and run.
add_test(NAME app_install_consumer
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/install/install_consumer.sh ${CMAKE_COMMAND}
                 ${CMAKE_BINARY_DIR} ${CMAKE_CURRENT_BINARY_DIR}/install_consumer
                 ${CMAKE_SOURCE_DIR} ${CMAKE_CXX_COMPILER} ${CMAKE_INSTALL_BINDIR}
                 ${CMAKE_INSTALL_DATADIR} ${CMAKE_CXX_COMPILER_LAUNCHER})
set_tests_properties(app_install_consumer PROPERTIES LABELS app ENVIRONMENT "${mpi_env}"
                     TIMEOUT 300)

# Where each method stops working (label extremes): tests/extremes/CMakeLists.txt.
add_subdirectory(extremes)


# catena run --error-bar (Richardson from the runs at 2 dt and 4 dt): on the plucked string
# the estimate of the run's error on the middle node's track lies within a factor of 3 of
# the true error against a run at a 16 (HHT) or 20 (Radau IIA) times smaller step
# (check_error_bar.py); measured ratios 1.10 and 1.37, observed orders 1.89 and 4.48.
foreach(method hht radau)
  if(method STREQUAL "hht")
    set(method_sets --set integrator.type=hht --set integrator.stages=~)
    set(dt 0.02)
    set(reference_dt 0.00125)
  else()
    set(method_sets)
    set(dt 0.1)
    set(reference_dt 0.005)
  endif()
  catena_app_test(error_bar_string_${method} 0
                  "^  node [0-9]+ +probe_rms +\\+[0-9.e-]+ m  \\(observed order"
                  ${app} run meshes/taut_string.yaml ${method_sets} --set integrator.dt=${dt}
                  --error-bar --quiet -o ${CMAKE_CURRENT_BINARY_DIR}/error_bar_${method}.h5)
  catena_app_test(error_bar_string_${method}_reference 0 "done at t = 5 s"
                  ${app} run meshes/taut_string.yaml ${method_sets}
                  --set integrator.dt=${reference_dt} --quiet
                  -o ${CMAKE_CURRENT_BINARY_DIR}/error_bar_${method}_reference.h5)
  set_tests_properties(app_error_bar_string_${method} PROPERTIES
                       FIXTURES_SETUP error_bar_${method})
  set_tests_properties(app_error_bar_string_${method}_reference PROPERTIES
                       FIXTURES_SETUP error_bar_${method})
  catena_app_check(error_bar_within_factor_3_${method} "error_bar_${method}" check_error_bar.py
                   ${CMAKE_CURRENT_BINARY_DIR}/error_bar_${method}.h5
                   ${CMAKE_CURRENT_BINARY_DIR}/error_bar_${method}_reference.h5)
endforeach()
# --error-bar-ranks K: the comparisons on the last K ranks beside the run (two at once on 2
# ranks, one after the other on 1) give the error bar of --error-bar, to 1e-9; a run that
# ends early stops its comparisons (the stop hook on the run's rank only: MPMD mpirun).
set(error_bar_hht_sets --set integrator.type=hht --set integrator.stages=~)
catena_app_test(error_bar_string_hht_ranks_2 0
                "error bar: the runs at dt 0.04 s on rank 1 and 0.08 s on rank 2, beside this run"
                ${MPIEXEC_EXECUTABLE} -n 3 --oversubscribe ${app} run meshes/taut_string.yaml
                ${error_bar_hht_sets} --set integrator.dt=0.02 --error-bar-ranks 2 --quiet
                -o ${CMAKE_CURRENT_BINARY_DIR}/error_bar_hht_ranks_2.h5)
catena_app_test(error_bar_string_hht_ranks_1 0
                "error bar: the runs at dt 0.04 s and 0.08 s one after the other on rank 1"
                ${MPIEXEC_EXECUTABLE} -n 2 --oversubscribe ${app} run meshes/taut_string.yaml
                ${error_bar_hht_sets} --set integrator.dt=0.02 --error-bar-ranks 1 --quiet
                -o ${CMAKE_CURRENT_BINARY_DIR}/error_bar_hht_ranks_1.h5)
set_tests_properties(app_error_bar_string_hht_ranks_2 app_error_bar_string_hht_ranks_1
                     PROPERTIES FIXTURES_SETUP error_bar_hht_ranks)
foreach(k 1 2)
  catena_app_check(error_bar_ranks_${k}_as_after_the_run "error_bar_hht;error_bar_hht_ranks"
                   check_error_bar.py ${CMAKE_CURRENT_BINARY_DIR}/error_bar_hht_ranks_${k}.h5
                   ${CMAKE_CURRENT_BINARY_DIR}/error_bar_hht_reference.h5
                   ${CMAKE_CURRENT_BINARY_DIR}/error_bar_hht.h5)
endforeach()
catena_app_test(error_bar_ranks_stop_with_the_run 143
                "no error bar for .*: the run at dt 0.001 s was stopped at t = [0-9.]+ s, as the run it compares with ended early"
                ${MPIEXEC_EXECUTABLE} --oversubscribe -n 1 -x CATENA_STOP_AFTER_STEPS=5 ${app}
                run meshes/taut_string.yaml ${error_bar_hht_sets} --set integrator.dt=0.0005
                --error-bar-ranks 2 --quiet -o ${CMAKE_CURRENT_BINARY_DIR}/error_bar_stop.h5 :
                -n 2 ${app} run meshes/taut_string.yaml ${error_bar_hht_sets}
                --set integrator.dt=0.0005 --error-bar-ranks 2 --quiet
                -o ${CMAKE_CURRENT_BINARY_DIR}/error_bar_stop.h5)
set_tests_properties(app_error_bar_ranks_stop_with_the_run PROPERTIES PROCESSORS 3)
# Groups of several ranks: the run on 2 ranks, the comparisons on 3 (2 dt on two of them).
catena_app_test(error_bar_ranks_groups_of_several 0
                "error bar: the runs at dt 0.04 s on ranks 2-3 and 0.08 s on rank 4, beside this run"
                ${MPIEXEC_EXECUTABLE} -n 5 --oversubscribe ${app} run meshes/taut_string.yaml
                ${error_bar_hht_sets} --set integrator.dt=0.02 --error-bar-ranks 3 --quiet
                -o ${CMAKE_CURRENT_BINARY_DIR}/error_bar_hht_ranks_3.h5)
set_tests_properties(app_error_bar_ranks_groups_of_several PROPERTIES
                     FIXTURES_SETUP error_bar_hht_ranks)
catena_app_check(error_bar_ranks_3_as_after_the_run "error_bar_hht;error_bar_hht_ranks"
                 check_error_bar.py ${CMAKE_CURRENT_BINARY_DIR}/error_bar_hht_ranks_3.h5
                 ${CMAKE_CURRENT_BINARY_DIR}/error_bar_hht_reference.h5
                 ${CMAKE_CURRENT_BINARY_DIR}/error_bar_hht.h5)
catena_app_test(error_bar_ranks_zero_exit_2 2
                "--error-bar-ranks 0: accepted: a whole number of ranks >= 1" ${app} run
                meshes/taut_string.yaml --error-bar-ranks 0)
catena_app_test(error_bar_ranks_all_exit_2 2
                "--error-bar-ranks 2 leaves no rank for the run itself: the job has 2 ranks"
                ${MPIEXEC_EXECUTABLE} -n 2 --oversubscribe ${app} run meshes/taut_string.yaml
                --error-bar-ranks 2 -o ${CMAKE_CURRENT_BINARY_DIR}/error_bar_all.h5)
catena_app_test(error_bar_ranks_not_of_study_exit_2 2
                "'--error-bar-ranks' is an option of run" ${app} study meshes/taut_string.yaml
                --error-bar-ranks 1)
# The error bar stays with the output: catena stats shows it under the table (and in --json).
catena_app_test(error_bar_pantograph 0 "^  leading +force_rms_filtered +\\+[0-9.e-]+ N" ${app} run
                meshes/pantograph_wire.yaml --set analysis.duration=0.3 --error-bar --quiet
                -o ${CMAKE_CURRENT_BINARY_DIR}/error_bar_pantograph.h5)
set_tests_properties(app_error_bar_pantograph PROPERTIES FIXTURES_SETUP error_bar_pantograph)
catena_app_test(error_bar_in_stats 0
                "^  leading +std +[+-][0-9.e-]+ %  \\((observed order [0-9.]+|rough)\\)$" ${app}
                stats ${CMAKE_CURRENT_BINARY_DIR}/error_bar_pantograph.h5 --section 10 15)
catena_app_test(error_bar_in_stats_json 0
                "\"error_bar\": \\{\"dt\": 2e-04, \"coarse_dt\": \\[4e-04, 8e-04\\], \"entries\": \\[\\{\"part\": \"leading\", \"measure\": \"mean\""
                ${app} stats ${CMAKE_CURRENT_BINARY_DIR}/error_bar_pantograph.h5 --section 10 15
                --json)
set_tests_properties(app_error_bar_in_stats app_error_bar_in_stats_json PROPERTIES
                     FIXTURES_REQUIRED error_bar_pantograph)
catena_app_test(error_bar_refuses_adaptive 2 "'--error-bar'.*needs fixed steps" ${app} run
                meshes/taut_string.yaml --set integrator.adaptive=true --error-bar
                -o ${CMAKE_CURRENT_BINARY_DIR}/error_bar_adaptive.h5)
catena_app_test(error_bar_refuses_static 2 "'--error-bar'.*analysis is static" ${app} run
                meshes/hanging_cable.yaml --error-bar
                -o ${CMAKE_CURRENT_BINARY_DIR}/error_bar_static.h5)
catena_app_test(error_bar_is_an_option_of_run 2 "'--error-bar' is an option of run" ${app}
                check meshes/taut_string.yaml --error-bar)

# The scaling study (scaling/scaling_study.py) and its Slurm script on a 500 m line: the
# table's columns, strong and weak lines, the same motion on 1 and 2 ranks, efficiencies
# from the measured times, reuse of finished runs, refused options. About 15 s.
add_test(NAME app_scaling_study
         COMMAND /usr/bin/python3 ${CMAKE_CURRENT_SOURCE_DIR}/app/check_scaling_study.py
                 $<TARGET_FILE:moving_load_benchmark> ${MPIEXEC_EXECUTABLE}
                 ${CMAKE_CURRENT_BINARY_DIR}
         WORKING_DIRECTORY ${CMAKE_SOURCE_DIR})
# Long (both cores for about 10 s; CI time): a benchmark's harness, run with -L long.
set_tests_properties(app_scaling_study PROPERTIES LABELS "app;long" ENVIRONMENT "${mpi_env}"
                     PROCESSORS 2 TIMEOUT 300)
# The benchmarks name a bad option and its accepted values, or the scene reader's error for
# a value only it checks (exit 2), instead of aborting with a backtrace.
catena_app_test(moving_load_benchmark_short_line 2 "-length 10: at least one span, 62.5 m"
                $<TARGET_FILE:moving_load_benchmark> -length 10)
catena_app_test(moving_load_benchmark_bad_alpha 2 "'integrator.alpha': value 5 is out of range"
                $<TARGET_FILE:moving_load_benchmark> -length 125 -alpha 5)
catena_app_test(static_line_benchmark_bad_element 2 "-element: a length in .0, 62.5. m"
                $<TARGET_FILE:static_line_benchmark> -element 0)
