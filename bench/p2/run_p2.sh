#!/usr/bin/env bash
# P2 performance benchmark (docs/performance-p2.md; docs/benchmarks.md P2): two
# stacked elastic blocks with non-matching meshes and Coulomb friction, run in frix and in
# CalculiX (Debian package calculix-ccx, binary ccx) on the same nodes, elements, loads and
# penalty stiffnesses; writes a markdown table. Not a test: nothing here asserts a time.
#
# Usage: bench/p2/run_p2.sh [n ...]          (default: 8 16 24; lower block n x n x n/2)
# Environment:
#   FRIX        the frix executable (default: <repo>/build/frix)
#   CCX         the CalculiX executable (default: ccx)
#   P2_WORK     directory for generated inputs and run outputs (default: /tmp/frix-p2)
#   P2_RESULTS  directory of the results (default: <repo>/bench/results)
#   P2_DATE     date tag of the result file (default: today, YYYY-MM-DD)
# Both codes run single-threaded (OMP_NUM_THREADS=1, OPENBLAS_NUM_THREADS=1), one after the
# other, timed with GNU time. Output: <P2_RESULTS>/p2_<date>.md, p2_<date>_machine.txt and
# p2_<date>_n<n>_pressure.png (contact stresses along the centre row).
set -euo pipefail

script_dir=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
repo_dir=$(cd "${script_dir}/../.." && pwd)
frix=${FRIX:-${repo_dir}/build/frix}
ccx=${CCX:-ccx}
work_dir=${P2_WORK:-/tmp/frix-p2}
results_dir=${P2_RESULTS:-${repo_dir}/bench/results}
date_tag=${P2_DATE:-$(date -u +%Y-%m-%d)}
sizes=("$@")
if [ ${#sizes[@]} -eq 0 ]; then sizes=(8 16 24); fi

if [ ! -x "${frix}" ]; then
   echo "run_p2.sh: frix executable not found: ${frix} (set FRIX)" >&2
   exit 2
fi
if ! command -v "${ccx}" > /dev/null; then
   echo "run_p2.sh: CalculiX not found: ${ccx} (apt-get install calculix-ccx, or set CCX)" >&2
   exit 2
fi
if [ ! -x /usr/bin/time ]; then
   echo "run_p2.sh: /usr/bin/time (GNU time) is needed" >&2
   exit 2
fi
export OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1
mkdir -p "${work_dir}" "${results_dir}"
machine="${results_dir}/p2_${date_tag}_machine.txt"
{
   echo "date: $(date -u '+%Y-%m-%d %H:%M UTC')"
   echo "host_cpu: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2- | sed 's/^ *//')"
   # nproc honours OMP_NUM_THREADS (exported above): count the processors without it
   echo "nproc: $(env -u OMP_NUM_THREADS -u OMP_THREAD_LIMIT nproc) (shared with other jobs)"
   echo "memory: $(free -m | awk '/^Mem:/ {print $2 " MiB"}')"
   echo "kernel: $(uname -r)"
   echo "frix: ${frix} ($(gfortran --version | head -1))"
   echo "calculix: $(${ccx} -v 2>&1 | grep -m1 Version | sed 's/^ *//') ($(dpkg-query -W -f='${Package} ${Version}' calculix-ccx 2>/dev/null || echo 'not a Debian package'))"
   echo "threads: OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1"
   echo "load_before: $(cut -d' ' -f1-3 /proc/loadavg)"
} > "${machine}"

for n in "${sizes[@]}"; do
   /usr/bin/python3 "${script_dir}/p2_generate.py" "${n}" "${work_dir}"
   rm -rf "${work_dir}/frix_n${n}"
   echo "run_p2.sh: n = ${n}: frix" >&2
   echo "load_before_frix_n${n}: $(cut -d' ' -f1-3 /proc/loadavg)" >> "${machine}"
   ( cd "${work_dir}" && /usr/bin/time -f "wall %e s rss %M kB user %U s sys %S s" -a -o "frix_n${n}.time" \
        "${frix}" "p2_n${n}.dck" --out "frix_n${n}" > "frix_n${n}.log" 2>&1 ) || \
      echo "run_p2.sh: frix failed for n = ${n} (see ${work_dir}/frix_n${n}.log)" >&2
   cat "${work_dir}/frix_n${n}.time" >> "${work_dir}/frix_n${n}.log"; rm -f "${work_dir}/frix_n${n}.time"
   echo "run_p2.sh: n = ${n}: CalculiX" >&2
   echo "load_before_ccx_n${n}: $(cut -d' ' -f1-3 /proc/loadavg)" >> "${machine}"
   ( cd "${work_dir}" && rm -f "p2_n${n}.dat" "p2_n${n}.sta" "p2_n${n}.cvg" && \
        /usr/bin/time -f "wall %e s rss %M kB user %U s sys %S s" -a -o "ccx_n${n}.time" \
        "${ccx}" -i "p2_n${n}" > "ccx_n${n}.log" 2>&1 ) || \
      echo "run_p2.sh: CalculiX failed for n = ${n} (see ${work_dir}/ccx_n${n}.log)" >&2
   cat "${work_dir}/ccx_n${n}.time" >> "${work_dir}/ccx_n${n}.log"; rm -f "${work_dir}/ccx_n${n}.time"
done
echo "load_after: $(cut -d' ' -f1-3 /proc/loadavg)" >> "${machine}"

/usr/bin/python3 "${script_dir}/p2_compare.py" "${work_dir}" "${results_dir}/p2_${date_tag}.md" \
   --sizes "${sizes[@]}" --img-prefix "${results_dir}/p2_${date_tag}" --machine "${machine}"
echo "run_p2.sh: wrote ${results_dir}/p2_${date_tag}.md" >&2
