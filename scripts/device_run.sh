#!/usr/bin/env bash
# Runs on the GPU machine from the repository root, with gpu-bundle/ carried
# there: GPU tests, compute-sanitizer and the benchmarks, everything written
# under $OUT. Usage: device_run.sh [tests] [sanitize] [bench] [cli] [study] [float] [profile] [profile-lattice] [profile-source] [profile-coloured]
# (default: tests sanitize bench)
set -uo pipefail
b=$(cd "$(dirname "$0")" && pwd)
out=${OUT:-/tmp/out}
mkdir -p "$out"
export TETSMOOTH_GIT_SHA=$(cat "$b/GIT_SHA")
export TETSMOOTH_MESH_CACHE=/tmp/tetsmooth-meshes
steps=${*:-tests sanitize bench}
# What made this folder: the steps and the commit of the bundle (the JSONs
# carry their own bench_smooth command lines).
echo "device_run.sh $steps, git $TETSMOOTH_GIT_SHA, $(date -u +%Y-%m-%dT%H:%M:%SZ)" > "$out/run.txt"
nvidia-smi --query-gpu=name,driver_version,memory.total,clocks.sm,clocks.max.sm --format=csv | tee "$out/device.txt"
nproc >> "$out/device.txt"
status=0
# Nsight Compute, where the machine has it (looked up by the profile steps).
find_ncu() { command -v ncu || ls /opt/nvidia/nsight-compute/*/ncu 2>/dev/null | head -1; }
# Source counters (executed instructions and stall samples for each SASS
# instruction) of one launch of the kernels matching $2, after skipping $3,
# under bench_smooth with the remaining arguments: ncu_source_$1.csv and
# ncu_details_$1.txt, the tool's log in ncu_source_$1.log.
source_profile() {
  local name=$1 kernel=$2 skip=$3
  shift 3
  timeout 420 "$ncu" --clock-control none --kernel-name "regex:$kernel" --launch-skip "$skip" --launch-count 1 \
    --section SourceCounters --section WarpStateStats --section InstructionStats --section SpeedOfLight \
    --section Occupancy -o "$out/ncu_source_$name" "$b/bench_smooth" --no-cpu --benchmark_min_time=0.01 "$@" \
    > "$out/ncu_source_$name.log" 2>&1
  echo "ncu $name exit $?"
  "$ncu" --import "$out/ncu_source_$name.ncu-rep" --page source --csv --print-source sass > "$out/ncu_source_$name.csv"
  echo "source export $? ($(wc -l < "$out/ncu_source_$name.csv") lines)"
  "$ncu" --import "$out/ncu_source_$name.ncu-rep" --page details > "$out/ncu_details_$name.txt"
}
for step in $steps; do
  case $step in
    tests)
      "$b/test_gpu_topology" 2>&1 | tee "$out/gpu_tests.log" | tail -3 || status=1
      "$b/test_gpu_smoother" 2>&1 | tee -a "$out/gpu_tests.log" | grep -E "differ|inverted|PASSED|FAILED|Failure" | tail -60 || status=1
      ;;
    sanitize)
      cs=$(command -v compute-sanitizer || echo /usr/local/cuda/bin/compute-sanitizer)
      {
        echo "== memcheck: every variant on the 5k model, and the stopping rule of each strategy"
        timeout 300 "$cs" --tool memcheck --error-exitcode 9 "$b/test_gpu_smoother" --gtest_filter='Variants/*:GpuSmoother.ColouredFormB*:GpuSmoother.Skipping*:GpuSmoother.ProgressReports*:GpuSmoother.StoppingRule*' 2>&1 | tail -8
        echo "memcheck exit ${PIPESTATUS[0]}"
        echo "== memcheck: GPU topology and colouring"
        timeout 200 "$cs" --tool memcheck --error-exitcode 9 "$b/test_gpu_topology" 2>&1 | tail -4
        echo "memcheck exit ${PIPESTATUS[0]}"
        # SingleBlock (A and B) and Coloured, adaptive, double and float: variant
        # indices of AllGpuVariants (Form, Layout, Strategy, Method, Precision).
        # racecheck and synccheck see shared memory and barriers; what blocks
        # exchange through global memory across grid.sync() is covered by the
        # tests (bit-identical repeated runs, agreement with the CPU). The lane
        # counts' test takes the coloured loop's unstaged path (8 and 16 lanes)
        # as well as its staged one (a warp a node). The progress quality's
        # test runs its block reductions.
        racy_filter='Variants/AllGpuVariants.AgainstCpuReference/0:*/1:*/24:*/25:*/32:*/33:GpuSmoother.ColouredIsBitIdenticalAcrossRuns:GpuSmoother.SkippingSettledNodesChangesNothing:GpuSmoother.ColouredLaneCountsAgree:GpuSmoother.ProgressReports*'
        for tool in racecheck synccheck; do
          echo "== $tool: SingleBlock and Coloured"
          timeout 200 "$cs" --tool $tool --error-exitcode 9 "$b/test_gpu_smoother" \
            --gtest_filter="$racy_filter" 2>&1 | grep -E "SingleBlock|Coloured|ERROR|Hazard|hazard|RACECHECK|SYNCCHECK|PASSED|FAILED" | tail -40
          echo "$tool exit ${PIPESTATUS[0]}"
        done
      } 2>&1 | tee "$out/sanitizers.log"
      ;;
    bench)
      # A quick look in both precisions: the 109k model against its CPU
      # baselines, and the lattice.
      for prec in double float; do
        "$b/bench_smooth" --precision=$prec --models=5k,109k --scaling=lattice-215 \
          --benchmark_filter='Memory|Serial/FormB/109k|Threads/FormB/109k|FormB/AoS/(Coloured|MultiBlock)/|FormB/SoA/Coloured/lattice' \
          --benchmark_repetitions=${REPS:-1} --benchmark_min_time=0.01 \
          --benchmark_out="$out/bench_quick_$prec.json" --benchmark_out_format=json 2>&1 | grep -v "^\[" | cut -c1-160 | tail -16
      done
      ;;
    float)
      # The CPU baselines of the 109k model come along, so the float GPU times
      # have their serial and threaded references in the same run.
      "$b/bench_smooth" --precision=float --models=5k,10k,59k,77k,109k --scaling=lattice-215 \
        --benchmark_filter='Memory|Serial/FormB/109k|Threads/FormB/109k|(FormB|Ordinary)/.*/(Coloured|MultiBlock)/' \
        --benchmark_repetitions=${REPS:-3} --benchmark_min_time=0.01 \
        --benchmark_out="$out/bench_float.json" --benchmark_out_format=json 2>&1 | grep -v "^\[" | cut -c1-160 | tail -30
      ;;
    profile)
      # Each kernel of one 109k Coloured double pipeline, timed alone by
      # Nsight Compute (clocks left as they are): where topology and
      # colouring spend their time. One row per launch in ncu_109k.csv.
      ncu=$(find_ncu)
      timeout 300 "$ncu" --clock-control none --metrics gpu__time_duration.sum --csv --launch-count 400 \
        "$b/bench_smooth" --no-cpu --models=109k --benchmark_filter='^FormB/AoS/Coloured/109k' \
        --benchmark_min_time=0.01 > "$out/ncu_109k.csv" 2> "$out/ncu_109k.err"
      echo "ncu exit $? ($(wc -l < "$out/ncu_109k.csv") lines)"
      ;;
    profile-lattice)
      # Where a lattice-215 sweep's time goes, in float: Nsight Compute on the
      # whole 100-sweep coloured loop and on one mid-run MultiBlock sweep, its
      # tet quality pass and its node pass (DRAM traffic, cache hit rates,
      # instructions, warp stalls). The lattice is generated once and cached
      # on disk for the second run.
      ncu=$(find_ncu)
      for pick in "Coloured coloured_loop_kernel 0 1" "MultiBlock tet_quality_kernel|sweep_kernel 100 2"; do
        set -- $pick
        timeout 420 "$ncu" --clock-control none --kernel-name "regex:$2" --launch-skip "$3" --launch-count "$4" \
          --section SpeedOfLight --section MemoryWorkloadAnalysis --section WarpStateStats --section Occupancy \
          --metrics dram__bytes_read.sum,dram__bytes_write.sum,lts__t_sector_hit_rate.pct,smsp__inst_executed.sum \
          "$b/bench_smooth" --no-cpu --precision=float --scaling=lattice-215 \
          --benchmark_filter="^FormB/AoS/$1/lattice" --benchmark_min_time=0.01 > "$out/ncu_lattice_$1.txt" 2>&1
        echo "ncu $1 exit $?"
        grep -E "^  [a-z].*\(|dram__bytes|lts__t_sector_hit|inst_executed|Duration|DRAM Throughput|Memory Throughput|L2 Hit|L1/TEX Hit|Achieved Occupancy|Issue Slots|Stall" "$out/ncu_lattice_$1.txt" | cut -c1-140 | head -40
      done
      ;;
    profile-source)
      # Nsight Compute's source counters for one mid-run float MultiBlock
      # node pass of lattice-215: executed instructions and stall samples for
      # each SASS instruction (ncu_source_MultiBlock.csv), to see what a
      # round of the star test costs and where it waits.
      ncu=$(find_ncu)
      source_profile MultiBlock sweep_kernel 50 --precision=float --scaling=lattice-215 \
        --benchmark_filter='^FormB/AoS/MultiBlock/lattice'
      ;;
    profile-coloured)
      # Nsight Compute's source counters for the 109k model's whole coloured
      # loop (one cooperative launch), double and float:
      # where a node's chain of loads and arithmetic waits
      # (ncu_source_Coloured_<precision>.csv, one row per SASS instruction).
      ncu=$(find_ncu)
      for prec in double float; do
        source_profile "Coloured_$prec" coloured_loop_kernel 0 --precision=$prec --models=109k \
          --benchmark_filter='^FormB/AoS/Coloured/109k'
      done
      ;;
    cli)
      # The command-line tool end to end on the GPU (the CI machine has
      # none): a 3.4M-node lattice smoothed by each strategy with a JSON
      # report, checked by the tool's own quality command, and one long run
      # on a pseudo-terminal, whose progress line run_on_pty.py keeps.
      {
        mesh=/tmp/cli_lattice150.tsm
        "$b/tetsmooth" generate lattice-150 -o $mesh -q
        echo "generate exit $?"
        for strategy in coloured multiblock; do
          "$b/tetsmooth" smooth $mesh -o /tmp/cli_$strategy.vtu --device cuda --strategy $strategy \
            --report "$out/cli_report_$strategy.json" -q
          echo "smooth --strategy $strategy exit $?"
          "$b/tetsmooth" quality /tmp/cli_$strategy.vtu --json > "$out/cli_quality_$strategy.json"
          echo "quality exit $?"
        done
        python3 "$b/run_on_pty.py" "$b/tetsmooth" smooth $mesh -o /tmp/cli_progress.tsm --device cuda \
          --strategy multiblock --tol 0 --max-iter 400
        echo "smooth on a terminal exit $?"
      } 2>&1 | tee "$out/cli.log" | tail -40
      if grep -qE "exit [1-9]" "$out/cli.log"; then status=1; fi
      ;;
    study)
      "$b/bench_smooth" --scaling=lattice-215 --benchmark_repetitions=${REPS:-3} --benchmark_min_time=0.01 \
        --benchmark_out="$out/bench_smooth.json" --benchmark_out_format=json 2>&1 | cut -c1-160 | tail -40
      ;;
  esac
done
exit $status
