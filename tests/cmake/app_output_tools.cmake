# Around the runs: the Slurm script, launcher loss, catena stats on synthetic files, run
# status, export and plot.
# Included by tests/CMakeLists.txt, whose helpers (catena_app_test, catena_app_check) and
# variables (app, expect, mpi_env) it uses.

# The Slurm batch script (scaling/slurm/catena_run.sbatch) with fake srun, scancel and
# scontrol: the time-limit warning stops catena with a checkpoint and requeues, the job
# resumes with --restart (srun, then mpirun -n 2), SIGTERM (scancel) is not requeued, a
# complete output is left alone, a scene error is not requeued. About 15 s.
add_test(NAME app_slurm_resume
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/app/slurm_resume.sh ${app} ${MPIEXEC_EXECUTABLE}
                 ${CMAKE_CURRENT_BINARY_DIR}
         WORKING_DIRECTORY ${CMAKE_SOURCE_DIR})
set_tests_properties(app_slurm_resume PROPERTIES LABELS app ENVIRONMENT "${mpi_env}"
                     TIMEOUT 300 PROCESSORS 2)
# Write failures (docs/output.md, "When the output cannot be written"): a write failing on
# one rank — injected with CATENA_FAULT_INJECT_WRITE, or a real full disk (a small tmpfs;
# skipped where mounting is not permitted) — ends every rank with exit 4 and one message,
# within a time limit, keeping the last checkpoint or the previous result.
foreach(case dynamic_sample dynamic_flush dynamic_checkpoint static_np1 static_np2
             full_disk_static_np1 full_disk_static_np2 full_disk_dynamic_np2)
  add_test(NAME app_write_failure_${case}
           COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/app/write_failures.sh ${app}
                   ${MPIEXEC_EXECUTABLE} ${CMAKE_CURRENT_BINARY_DIR} ${case}
           WORKING_DIRECTORY ${CMAKE_SOURCE_DIR})
  set(ranks 2)
  if(case MATCHES "_np1$")
    set(ranks 1)
  endif()
  set_tests_properties(app_write_failure_${case} PROPERTIES LABELS app ENVIRONMENT "${mpi_env}"
                       TIMEOUT 300 PROCESSORS ${ranks} SKIP_RETURN_CODE 77)
endforeach()
# Restarts on the same rank count continue bit for bit, and to the Newton tolerance on
# another rank count. The core cases (HHT with contact and local Newton, Radau IIA, a linear
# and a modal structure, a crash after a checkpoint, np 2 -> 1) in the default run; the
# others (adaptive steps, step doubling, the linearly implicit step, the last step, two
# restarts, format 1) labelled long. Stops come from step counts, not the wall clock, so
# the cases need no core to themselves.
foreach(group core more)
  add_test(NAME app_restart_exact_${group}
           COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/app/restart_exact.sh ${app}
                   ${MPIEXEC_EXECUTABLE} ${CMAKE_CURRENT_BINARY_DIR} ${group}
           WORKING_DIRECTORY ${CMAKE_SOURCE_DIR})
  set_tests_properties(app_restart_exact_${group} PROPERTIES LABELS app ENVIRONMENT "${mpi_env}"
                       TIMEOUT 900 PROCESSORS 2)
endforeach()
set_tests_properties(app_restart_exact_more PROPERTIES LABELS "app;long")
# The testing hooks refuse what is not a step count.
catena_app_test(test_hook_not_a_count 2
                "CATENA_STOP_AFTER_STEPS = 'often'. accepted: a positive integer"
                env CATENA_STOP_AFTER_STEPS=often ${app} run meshes/pantograph_wire.yaml
                --set analysis.duration=0.001 -o ${CMAKE_CURRENT_BINARY_DIR}/app_test_hook.h5)
catena_app_test(restart_static_scene 2 "--restart continues a dynamic run"
                ${app} run meshes/default.yaml --restart
                -o ${CMAKE_CURRENT_BINARY_DIR}/app_restart_static.h5)
# spans: auto sizes the line from the duration: a longer restart is refused with the reason.
catena_app_test(restart_auto_spans_longer 2
                "cannot restart from this checkpoint: .*catenary\\.spans: auto sized this scene's line \\(5 spans\\) for analysis\\.duration = 1\\.2 s: a restart continues the checkpoint's line and cannot lengthen it"
                bash -c "$0 run tests/data/app/catenary_pantograph.yaml --set catenary.spans=auto --set analysis.duration=0.02 -o $1 > /dev/null && $0 run tests/data/app/catenary_pantograph.yaml --set catenary.spans=auto --set analysis.duration=1.2 -o $1 --restart"
                ${app} ${CMAKE_CURRENT_BINARY_DIR}/app_restart_auto_spans.h5)
catena_app_test(restart_without_checkpoint 2 "cannot restart from this checkpoint: no such file"
                ${app} run meshes/cable_pendulum.yaml --restart
                -o ${CMAKE_CURRENT_BINARY_DIR}/app_no_checkpoint.h5)
# A pantograph on a wire (moving penalty contact) at np 2.
catena_app_test(run_pantograph_wire_np2 0 "done at t = 0.3 s"
                ${MPIEXEC_EXECUTABLE} -n 2 --oversubscribe ${app} run meshes/pantograph_wire.yaml
                --set analysis.duration=0.3
                -o ${CMAKE_CURRENT_BINARY_DIR}/app_pantograph_wire.h5)
catena_app_test(run_damped_cantilever 0 "done at t = 1 s" ${app} run meshes/damped_cantilever.yaml
                -o ${CMAKE_CURRENT_BINARY_DIR}/app_cantilever.h5)
catena_app_test(dynamics_min_step_exit_3 3 "below its minimum at t = .*dt_min"
                ${app} run meshes/cable_pendulum.yaml --set integrator.adaptive=true
                --set integrator.rtol=1e-12 --set integrator.atol=1e-15
                --set integrator.dt_min=1e-4
                -o ${CMAKE_CURRENT_BINARY_DIR}/app_pendulum_fail.h5)
# catena stats: EN 50318 contact-force statistics of synthetic dynamic outputs written by
# tests/app/make_stats_fixture.py (h5py): the JSON keys, every number against an
# independent NumPy evaluation (check_stats.py), the table, and each input error (exit 2).
set(stats_dir ${CMAKE_CURRENT_BINARY_DIR}/stats)
add_test(NAME app_stats_fixture
         COMMAND /usr/bin/python3 ${CMAKE_CURRENT_SOURCE_DIR}/app/make_stats_fixture.py
                 ${stats_dir})
set_tests_properties(app_stats_fixture PROPERTIES LABELS app FIXTURES_SETUP stats_files)
set(num "-?[0-9][0-9.e+-]*")
function(catena_stats_test name code regex)
  catena_app_test(stats_${name} ${code} ${regex} ${app} stats ${ARGN})
  set_tests_properties(app_stats_${name} PROPERTIES FIXTURES_REQUIRED stats_files)
endfunction()
string(CONCAT json_keys "^  \\{\"name\": \"trailing\", \"speed_kmh\": ${num}, "
       "\"section\": \\[100, 300\\], \"coverage\": 1, \"reached_section\": true, \"mean\": ${num}, "
       "\"std\": ${num}, \"stat_max\": ${num}, \"stat_min\": ${num}, \"max\": ${num}, "
       "\"min\": ${num}, \"contact_loss_percent\": ${num}, "
       "\"max_uplift_at_support\": ${num}, \"acceptance\": null\\}$")
catena_stats_test(json 0 "${json_keys}" ${stats_dir}/stats_run.h5 --json)
# A cutoff whose two periods outlast the record: refused, not statistics of the filter's
# start-up (σ = 0 and the first sample as mean, minimum and maximum).
catena_stats_test(cutoff_below_record 2 "'--cutoff': --cutoff 0.001 Hz: the record lasts .* s, shorter than two periods"
                  ${stats_dir}/stats_run.h5 --cutoff 0.001)
# A sample time that is not a number (a damaged file) is named, not passed over.
catena_stats_test(nan_time 2 "'/time': the time of sample 20 is not a finite number"
                  ${stats_dir}/stats_nan_time.h5)
# catena plot of a file that is no result (a checkpoint) is refused before the plot script
# reads it (a Python traceback and exit 4 before).
catena_app_test(plot_checkpoint_exit_2 2
                "'format': the file's format is 'catena-checkpoint-3', not a Catena result"
                sh -c "${app} run meshes/cable_pendulum.yaml --set analysis.duration=0.01 -o ${CMAKE_CURRENT_BINARY_DIR}/plot_chk.h5 > /dev/null && ${app} plot ${CMAKE_CURRENT_BINARY_DIR}/plot_chk.h5.chk -o ${CMAKE_CURRENT_BINARY_DIR}/plot_chk")
# An export to a place that cannot be written is the output's failure (exit 4).
catena_app_test(export_unwritable_exit_4 4
                "output could not be written: cannot write '/proc/x_contact.csv'"
                ${app} export ${stats_dir}/stats_run.h5 -o /proc/x)
set_tests_properties(app_export_unwritable_exit_4 PROPERTIES FIXTURES_REQUIRED stats_files)
add_test(NAME app_stats_values
         COMMAND /usr/bin/python3 ${CMAKE_CURRENT_SOURCE_DIR}/app/check_stats.py ${app}
                 ${stats_dir})
set_tests_properties(app_stats_values PROPERTIES LABELS app FIXTURES_REQUIRED stats_files
                     ENVIRONMENT "${mpi_env}")
catena_stats_test(table 0
                  "leading +250.0 +2881 +116.12 +20.89 +178.79 +53.46 +145.00 +85.00 +0.00 +50.00"
                  ${stats_dir}/stats_run.h5)
catena_stats_test(no_support_in_section 0 "\"max_uplift_at_support\": null, \"acceptance\": null\\}"
                  ${stats_dir}/stats_run.h5 --section 10 50 --json)
catena_stats_test(no_support_note 0 "note: no registration .*\\[10, 50\\] m"
                  ${stats_dir}/stats_run.h5 --section 10 50)
# A run still going, crashed or interrupted: read with a warning, over what it covered.
catena_stats_test(running_warning 0 "warning: the run did not finish \\(status 'running'\\)"
                  ${stats_dir}/stats_running.h5)
catena_stats_test(interrupted_covered 0 "leading: covered \\[100, 201.389\\] m, 51 % of the section"
                  ${stats_dir}/stats_interrupted.h5)
catena_stats_test(short_complete_covered 0 "warning: the record does not cover the whole section for every pantograph"
                  ${stats_dir}/stats_short.h5)
catena_stats_test(interrupted_before_section_exit_2 2
                  "stopped \\(status 'interrupted'\\) at t = 1 s, before any pantograph reached"
                  ${stats_dir}/stats_interrupted_early.h5)
# The EN 50318 ranges, when the run declares them (catenary.acceptance) or --ranges asks.
catena_stats_test(acceptance_in_range 0 "  mean F_m +116.12 N +110 – 120 +✓$"
                  ${stats_dir}/stats_acceptance.h5)
catena_stats_test(acceptance_out_of_range 0
                  "  standard deviation σ +20.89 N +26 – 31 +✗ out of range$"
                  ${stats_dir}/stats_acceptance.h5)
catena_stats_test(acceptance_count 0 "  4 of 8 statistics in range" ${stats_dir}/stats_acceptance.h5)
catena_stats_test(acceptance_by_option 0 "EN 50318 acceptance ranges at 300 km/h, pantograph trailing"
                  ${stats_dir}/stats_run.h5 --ranges en50318)
catena_app_test(stats_ranges_none 1 "^0$"
                sh -c "${app} stats ${stats_dir}/stats_acceptance.h5 --ranges none | grep -c 'EN 50318'")
set_tests_properties(app_stats_ranges_none PROPERTIES FIXTURES_REQUIRED stats_files)
catena_stats_test(unknown_acceptance_exit_2 2
                  "'acceptance': unknown acceptance ranges 'en50367' .*accepted: en50318"
                  ${stats_dir}/stats_unknown_acceptance.h5)
catena_app_test(stats_unknown_ranges_exit_2 2 "'--ranges': unknown acceptance ranges 'en50317'"
                ${app} stats x.h5 --ranges en50317)
catena_app_test(stats_partial_output_hint_exit_2 2
                "no_such_run.h5: no such file. the run has not finished: its output so far is .*no_such_run.part.h5"
                sh -c "touch ${stats_dir}/no_such_run.part.h5 && ${app} stats ${stats_dir}/no_such_run.h5")
set_tests_properties(app_stats_partial_output_hint_exit_2 PROPERTIES FIXTURES_REQUIRED stats_files)
# catena export and catena plot: their options, and the figures of a catenary run (the run
# of the --series steps test below).
catena_app_test(export_json_refused_exit_2 2 "unknown option '--json' for export. accepted: --csv"
                ${app} export x.h5 --json)
catena_app_test(plot_unknown_format_exit_2 2 "unknown format 'svg' in 'png,svg'. accepted: png, pdf"
                ${app} plot x.h5 --format png,svg)
catena_app_test(help_of_plot 0 "^Options of plot:$" ${app} plot --help)
catena_stats_test(no_section_exit_2 2 "no evaluation section.*--section X0 X1"
                  ${stats_dir}/stats_no_section.h5)
catena_stats_test(coarse_sampling_exit_2 2 "interval 0.01 s .* at most 0.005 s"
                  ${stats_dir}/stats_coarse.h5)
catena_stats_test(static_file_exit_2 2 "not a Catena dynamic output \\(format 'catena-static-1'"
                  ${stats_dir}/stats_static.h5)
catena_stats_test(no_pantographs_exit_2 2 "contact_force': missing: the run had no pantographs"
                  ${stats_dir}/stats_no_pantographs.h5)
catena_stats_test(old_format_exit_2 2
                  "stats_old_format.h5: 'format': missing \\(expected 'catena-transient-1'\\): .*older Catena"
                  ${stats_dir}/stats_old_format.h5)
catena_stats_test(other_format_exit_2 2
                  "stats_other_format.h5: 'format': .*format 'catena-transient-0', expected 'catena-transient-1'"
                  ${stats_dir}/stats_other_format.h5)
catena_stats_test(section_outside_exit_2 2 "'leading' has no sample in the evaluation section"
                  ${stats_dir}/stats_run.h5 --section 400 500)
catena_app_test(stats_missing_file_exit_2 2 "no_such_run.h5: no such file"
                ${app} stats no_such_run.h5)
catena_app_test(stats_not_hdf5_exit_2 2 "default.yaml: not an HDF5 file"
                ${app} stats meshes/default.yaml)
catena_app_test(stats_bad_section_exit_2 2 "'--section': X1 must be greater than X0"
                ${app} stats run.h5 --section 5 1)
catena_app_test(stats_bad_cutoff_exit_2 2 "'--cutoff': 'abc' is not a finite number"
                ${app} stats run.h5 --cutoff abc)
catena_app_test(stats_unknown_option_exit_2 2 "unknown option '--jsn' for stats"
                ${app} stats run.h5 --jsn)
