/* Thin glue between frix_cholmod_solver (Fortran) and CHOLMOD 3.0 (SuiteSparse 5.12), through
 * its 64-bit interface (cholmod_l_*: every index a SuiteSparse_long, so the factor may hold
 * more than 2^31 entries). It owns cholmod_common, whose layout is version dependent and never
 * mirrored in Fortran. The matrix is seen through a cholmod_sparse header pointing at the
 * Fortran arrays (0-based CSC, int64 indices, full pattern, stype = 1: only the upper triangle
 * is read). Return values are Common->status (0 ok, < 0 error, CHOLMOD_NOT_POSDEF = 1 for a
 * failed pivot). */
#include <stdlib.h>
#include <string.h>
#include <math.h>
#include "cholmod.h"

typedef SuiteSparse_long frix_long;
typedef struct { cholmod_common common; cholmod_factor *factor; } frix_cholmod_t;

void *frix_cholmod_create(void) {
  frix_cholmod_t *h = calloc(1, sizeof(frix_cholmod_t));
  if (!h) return NULL;
  cholmod_l_start(&h->common);
  h->common.print = 0;              /* library code prints nothing */
  h->common.error_handler = NULL;
  h->common.nmethods = 1;           /* use the caller's (METIS node) ordering only */
  h->common.method[0].ordering = CHOLMOD_GIVEN;
  h->common.postorder = 1;
  return h;
}

static void frix_header(cholmod_sparse *A, frix_long n, frix_long *p, frix_long *i, double *x) {
  memset(A, 0, sizeof(*A));
  A->nrow = A->ncol = (size_t)n; A->nzmax = (size_t)p[n];
  A->p = p; A->i = i; A->x = x; A->stype = 1;
  A->itype = CHOLMOD_LONG; A->xtype = CHOLMOD_REAL; A->dtype = CHOLMOD_DOUBLE;
  A->sorted = 1; A->packed = 1;
}

void frix_cholmod_release(void *handle) {
  frix_cholmod_t *h = handle;
  if (h && h->factor) cholmod_l_free_factor(&h->factor, &h->common);
}

void frix_cholmod_destroy(void *handle) {
  frix_cholmod_t *h = handle;
  if (!h) return;
  frix_cholmod_release(h);
  cholmod_l_finish(&h->common);
  free(h);
}

/* Symbolic analysis with the given fill-reducing permutation perm (Perm[k] = i: row i of A
 * is the k-th row of PAP'). lnz: predicted entries of L. */
int frix_cholmod_analyse(void *handle, frix_long n, frix_long *p, frix_long *i, double *x, frix_long *perm,
                         double *lnz) {
  frix_cholmod_t *h = handle;
  cholmod_sparse A;
  frix_cholmod_release(h);
  frix_header(&A, n, p, i, x);
  h->factor = cholmod_l_analyze_p(&A, perm, NULL, 0, &h->common);
  *lnz = h->common.lnz;
  return h->factor ? h->common.status : (h->common.status < 0 ? h->common.status : -1);
}

/* Numeric factorization. On CHOLMOD_NOT_POSDEF, *failed is the 0-based ORIGINAL equation
 * (L->Perm[L->minor]). Otherwise *min_pivot / *max_pivot are the extreme pivots (l_jj^2 for
 * LL', |d_j| for LDL') and *failed the original equation of the smallest one. */
int frix_cholmod_factorize(void *handle, frix_long n, frix_long *p, frix_long *i, double *x, frix_long *failed,
                           double *min_pivot, double *max_pivot) {
  frix_cholmod_t *h = handle;
  cholmod_factor *L = h->factor;
  cholmod_sparse A;
  frix_long *perm = L->Perm, j, s, jmin = 0;
  double d, dmin = INFINITY, dmax = 0.0, *lx;
  frix_header(&A, n, p, i, x);
  *failed = -1;
  cholmod_l_factorize(&A, L, &h->common);
  lx = L->x;
  if (h->common.status == CHOLMOD_NOT_POSDEF) {
    if (L->minor < (size_t)n) *failed = perm[L->minor];
    return h->common.status;
  }
  if (h->common.status < 0) return h->common.status;
  if (!L->is_super) {
    for (j = 0; j < n; j++) {  /* pivots in factor order */
      d = lx[((frix_long *)L->p)[j]];
      d = L->is_ll ? d * d : fabs(d);
      if (d < dmin) { dmin = d; jmin = j; }
      if (d > dmax) dmax = d;
    }
  } else {
    frix_long *super = L->super, *pi = L->pi, *px = L->px;
    for (s = 0; s < (frix_long)L->nsuper; s++) {
      frix_long nsrow = pi[s + 1] - pi[s];
      for (j = super[s]; j < super[s + 1]; j++) {
        d = lx[px[s] + (j - super[s]) * (nsrow + 1)];
        d = d * d;
        if (d < dmin) { dmin = d; jmin = j; }
        if (d > dmax) dmax = d;
      }
    }
  }
  if (n > 0) *failed = perm[jmin];
  *min_pivot = n > 0 ? dmin : 0.0;
  *max_pivot = dmax;
  return h->common.status;
}

/* x = A^-1 rhs with the current factor. */
int frix_cholmod_solve(void *handle, frix_long n, double *rhs, double *x) {
  frix_cholmod_t *h = handle;
  cholmod_dense B, *X;
  memset(&B, 0, sizeof(B));
  B.nrow = B.nzmax = B.d = (size_t)n; B.ncol = 1; B.x = rhs;
  B.xtype = CHOLMOD_REAL; B.dtype = CHOLMOD_DOUBLE;
  X = cholmod_l_solve(CHOLMOD_A, h->factor, &B, &h->common);
  if (!X) return h->common.status < 0 ? h->common.status : -1;
  memcpy(x, X->x, (size_t)n * sizeof(double));
  cholmod_l_free_dense(&X, &h->common);
  return h->common.status;
}

/* Peak and current bytes allocated by CHOLMOD through this handle. */
void frix_cholmod_memory(void *handle, double *peak, double *in_use) {
  frix_cholmod_t *h = handle;
  *peak = (double)h->common.memory_usage;
  *in_use = (double)h->common.memory_inuse;
}
