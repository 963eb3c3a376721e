/* P1 diagnostic (not part of frix): CHOLMOD alone on the sparsity pattern of the P1 cube.
 *
 * Builds the node-blocked pattern of an n x n x n HEX8 mesh (3 DOFs per node, every node
 * coupled to its 27 neighbours, the same pattern frix assembles, fixed base DOFs included),
 * fills it with a symmetric positive definite matrix (off-diagonal -1e-3, diagonal = 1 +
 * row count; values do not change the supernodal flop count), and for each fill-reducing
 * ordering prints CHOLMOD's predicted nnz(L), the factorization flop count (Common->fl),
 * the analyse and factorize wall times, the resulting GFLOP/s, and the number of values the
 * supernodal factor actually stores (L->xsize: nnz(L) plus the explicit zeros of relaxed
 * supernode amalgamation) and the largest update matrix of the supernodal factorization
 * (L->maxcsize, workspace beside the factor). CHOLMOD's 64-bit interface (cholmod_l_*), as frix calls it. It
 * answers: how many
 * flops does P1 need, and how close does frix's factorize time come to what CHOLMOD + the
 * BLAS can do on this machine.
 *
 * Build: gcc -O2 -I/usr/include/suitesparse bench/p1_cholmod_probe.c -o p1_cholmod_probe \
 *            -lcholmod -lm
 * Run:   ./p1_cholmod_probe n [ordering ...]   ordering: metis nesdis amd (default: all)
 *        P1_PROBE_ANALYSE_ONLY=1 skips the numeric factorization (nnz(L) and flops only).
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include "cholmod.h"

static double now(void) {
  struct timespec t;
  clock_gettime(CLOCK_MONOTONIC, &t);
  return t.tv_sec + 1e-9 * t.tv_nsec;
}

/* Upper triangle (stype = 1) of the node-blocked 27-neighbour pattern, CSC. */
static cholmod_sparse *cube_matrix(int n, cholmod_common *c) {
  SuiteSparse_long m = n + 1, nodes = m * m * m, neq = 3 * nodes, nz = 0, col, k;
  cholmod_sparse *A;
  SuiteSparse_long *p, *row;
  double *x;
  /* count */
  for (col = 0; col < neq; col++) {
    SuiteSparse_long node = col / 3, i = node % m, j = (node / m) % m, l = node / (m * m);
    for (int dl = -1; dl <= 1; dl++)
      for (int dj = -1; dj <= 1; dj++)
        for (int di = -1; di <= 1; di++) {
          SuiteSparse_long ii = i + di, jj = j + dj, ll = l + dl;
          if (ii < 0 || jj < 0 || ll < 0 || ii >= m || jj >= m || ll >= m) continue;
          SuiteSparse_long other = ii + m * (jj + m * ll);
          for (int d = 0; d < 3; d++)
            if (3 * other + d <= col) nz++;
        }
  }
  A = cholmod_l_allocate_sparse(neq, neq, nz, 1, 1, 1, CHOLMOD_REAL, c);
  p = A->p; row = A->i; x = A->x; k = 0;
  for (col = 0; col < neq; col++) {
    SuiteSparse_long node = col / 3, i = node % m, j = (node / m) % m, l = node / (m * m), start = k;
    p[col] = k;
    for (int dl = -1; dl <= 1; dl++)
      for (int dj = -1; dj <= 1; dj++)
        for (int di = -1; di <= 1; di++) {
          SuiteSparse_long ii = i + di, jj = j + dj, ll = l + dl;
          if (ii < 0 || jj < 0 || ll < 0 || ii >= m || jj >= m || ll >= m) continue;
          SuiteSparse_long other = ii + m * (jj + m * ll);
          for (int d = 0; d < 3; d++)
            if (3 * other + d <= col) { row[k] = 3 * other + d; x[k] = -1e-3; k++; }
        }
    x[k - 1] = 1.0 + (k - start); /* rows ascend: the last entry is the diagonal */
  }
  p[neq] = k;
  A->sorted = 1;
  return A;
}

int main(int argc, char **argv) {
  const char *all[] = {"metis", "nesdis", "amd"};
  int n = argc > 1 ? atoi(argv[1]) : 20, n_orders = argc > 2 ? argc - 2 : 3;
  const char **orders = argc > 2 ? (const char **)argv + 2 : all;
  cholmod_common c;
  cholmod_l_start(&c);
  int analyse_only = getenv("P1_PROBE_ANALYSE_ONLY") && atoi(getenv("P1_PROBE_ANALYSE_ONLY"));
  cholmod_sparse *A = cube_matrix(n, &c);
  printf("n %d equations %zu upper_nonzeros %zu\n", n, A->nrow, (size_t)((SuiteSparse_long *)A->p)[A->nrow]);
  for (int o = 0; o < n_orders; o++) {
    c.nmethods = 1;
    c.method[0].ordering = !strcmp(orders[o], "metis") ? CHOLMOD_METIS
                         : !strcmp(orders[o], "nesdis") ? CHOLMOD_NESDIS : CHOLMOD_AMD;
    c.postorder = 1;
    double t0 = now();
    cholmod_factor *L = cholmod_l_analyze(A, &c);
    double t1 = now();
    if (!analyse_only) cholmod_l_factorize(A, L, &c);
    double t2 = now();
    printf("ordering %-6s status %d lnz %.0f flops %.3e analyse_s %.3f factorize_s %.3f "
           "gflops %.1f supernodal %d stored_values %.0f max_update_values %.0f memory_peak_mb %.0f\n",
           orders[o], c.status, c.lnz, c.fl, t1 - t0, t2 - t1, analyse_only ? 0.0 : c.fl / (t2 - t1) / 1e9,
           L->is_super, (double)(L->is_super ? L->xsize : L->nzmax), (double)(L->is_super ? L->maxcsize : 0),
           c.memory_usage / 1048576.0);
    cholmod_l_free_factor(&L, &c);
  }
  cholmod_l_free_sparse(&A, &c);
  cholmod_l_finish(&c);
  return 0;
}
