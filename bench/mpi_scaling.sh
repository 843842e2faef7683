#!/usr/bin/env bash
# Strong scaling of a distributed still (docs/distributed.md): the same
# render on 1, 2 and 4 processes of one thread each, its wall time, the
# bytes rank 0 exchanged, and a model of the efficiency at 64 processes.
# Not a test. Usage (from the checkout, after building with MPI):
#   bench/mpi_scaling.sh [LANCER] [RUNS]
# Prints a Markdown table like the ones in bench/README.md. On a machine
# with fewer cores than processes the larger runs are oversubscribed: the
# table says how many cores there were.
set -euo pipefail
lancer=${1:-build/bin/lancer}
runs=${2:-3}
scene=scenes/cornell_box.pov
args=(render "$scene" -i path --width 256 --height 192 --spp 16 --threads 1 -o /tmp/lancer-mpi-bench.exr)
mpi=(mpirun --oversubscribe)
[ "$(id -u)" -eq 0 ] && mpi+=(--allow-run-as-root)
cores=$(nproc)
load_at_start=$(cut -d' ' -f1-3 /proc/loadavg)

# median of the numbers on stdin
median() { sort -g | awk '{v[NR]=$1} END {print (NR % 2) ? v[(NR+1)/2] : (v[NR/2] + v[NR/2+1]) / 2}'; }

declare -A wall render cpu bytes shares
for n in 1 2 4; do
  walls=() renders=() cpus=()
  for _ in $(seq "$runs"); do
    # /usr/bin/time counts every process mpirun started (its children).
    if [ "$n" -eq 1 ]; then
      out=$(/usr/bin/time -f 'time: %e %U %S' "$lancer" "${args[@]}" 2>&1)
    else
      out=$(/usr/bin/time -f 'time: %e %U %S' "${mpi[@]}" -np "$n" "$lancer" "${args[@]}" 2>&1)
    fi
    walls+=("$(echo "$out" | sed -n 's/^time: \([0-9.]*\) .*/\1/p')")
    cpus+=("$(echo "$out" | sed -n 's/^time: [0-9.]* \([0-9.]*\) \([0-9.]*\)/\1 + \2/p' | bc -l)")
    renders+=("$(echo "$out" | sed -n 's/.*(render \([0-9.]*\) s).*/\1/p' | tail -1)")
    bytes[$n]=$(echo "$out" | sed -n 's/.*; \([0-9.]*\) MB exchanged.*/\1/p' | tail -1)
    shares[$n]=$(echo "$out" | sed -n 's/.*tiles by process: \([0-9 ]*\)).*/\1/p' | tail -1)
  done
  wall[$n]=$(printf '%s\n' "${walls[@]}" | median)
  render[$n]=$(printf '%s\n' "${renders[@]}" | median)
  cpu[$n]=$(printf '%s\n' "${cpus[@]}" | median)
done

# Other work on the machine takes cores from a run: wall times compare
# only on an idle one. CPU seconds (all processes, user + system) show what
# distributing costs in work whatever the load.
echo "load average at start: $load_at_start"
echo
echo "| processes (1 thread each, $cores cores) | wall s | render s | render speed-up | CPU s | CPU vs 1 process | MB exchanged | tiles by process |"
echo "|---|---|---|---|---|---|---|---|"
for n in 1 2 4; do
  speedup=$(echo "${render[1]} / ${render[$n]}" | bc -l)
  printf '| %d%s | %.2f | %.2f | %.2f | %.2f | %.2f | %s | %s |\n' "$n" "$([ "$n" -gt "$cores" ] && echo ' (oversubscribed)')" \
    "${wall[$n]}" "${render[$n]}" "$speedup" "${cpu[$n]}" "$(echo "${cpu[$n]} / ${cpu[1]}" | bc -l)" \
    "${bytes[$n]:-0}" "${shares[$n]:-all}"
done

# The model, for a job worth 64 machines-cores: a 1920x1080 still at 256
# spp of this scene. A sample costs what the 1-process run measured (its
# render seconds scaled by the share of a core it got: CPU / wall); every
# process pays the start-up measured on 2 processes (wall minus render:
# mpirun, parse, plugins, integrator preparation), in parallel; 64-pixel
# tiles (510, 8 a process) leave each process waiting on average half a
# tile at the end; rank 0 receives each pixel's totals once (56 bytes) over
# a 1 GB/s link (10 Gb Ethernet), while rendering.
awk -v R="${render[1]}" -v CPU="${cpu[1]}" -v WALL="${wall[1]}" -v S="$(echo "${wall[2]} - ${render[2]}" | bc -l)" \
  -v P="$((256 * 192))" -v SPP=16 'BEGIN {
  n = 64; pixels = 1920 * 1080; spp = 256; tiles = 30 * 17; link = 1.0e9;
  per_sample = R * (CPU / WALL) / (P * SPP);
  W = per_sample * pixels * spp;          # one process, one core
  tail = W / tiles / 2;
  comm = pixels * 56 / link;
  t = S + W / n + tail;                   # transfer overlaps rendering
  printf "\nModel, 1920x1080 at 256 spp on %d processes (one core each): one process %.0f s of rendering; %d processes %.1f s = %.1f start-up + %.1f work + %.2f end-of-round wait (transfer %.2f s, %.0f MB, overlapped): efficiency %.2f (%.2f without start-up)\n", n, W, n, t, S, W / n, tail, comm, pixels * 56 / 1e6, (W + S) / (n * t), (W / n) / (W / n + tail)
}'
