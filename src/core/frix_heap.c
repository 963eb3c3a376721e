/* Heap policy of the frix program (glibc only; a no-op elsewhere).
 *
 * Each Newton iteration factorizes the tangent anew: CHOLMOD / UMFPACK allocate the numeric
 * factor (tens to hundreds of MB) and free it again. glibc serves blocks that large with
 * mmap and returns them to the kernel on free, so every factorization touches fresh pages:
 * in benchmark P2 (n = 16, 30 factorizations) 677 000 minor page faults and 17 s of system
 * time against 25 s of user time. With mmap off (M_MMAP_MAX 0) and no trimming of the heap's
 * top (M_TRIM_THRESHOLD at its maximum), freed blocks stay in the process and are reused:
 * 41 000 page faults, 0.3 s system time, CPU time halved; the peak memory can grow (5 to
 * 39 % there: blocks of different sizes fragment the heap). docs/performance.md. */
#include <limits.h>
#ifdef __GLIBC__
#include <malloc.h>
#endif

void frix_keep_freed_memory_c(void)
{
#ifdef __GLIBC__
   mallopt(M_MMAP_MAX, 0);
   mallopt(M_TRIM_THRESHOLD, INT_MAX);
#endif
}
