/* normals_qr_lanes.h - the column operations of normals_qr_pivot.c for one
 * vector width, included there once per width: QR_W (doubles to a
 * vector), QR_G (vectors to a pass) and QR_NAME(f) (the width's name for
 * f) are defined by the includer and undefined at the end here, so the
 * next width can define its own. QR_V is the vector of QR_W doubles and
 * QR_VL of as many 64-bit integers (GCC's vector extension). Lane l of a
 * vector is column c + l of one row; each lane's operations are the
 * scalar ones of the column loops, in their order (normals_qr_pivot.c
 * says why that gives the same bits). No include guard: meant to be
 * included more than once. */

typedef double QR_NAME(vd) __attribute__((vector_size(8 * QR_W)));
typedef long long QR_NAME(vl) __attribute__((vector_size(8 * QR_W)));
#define QR_V QR_NAME(vd)
#define QR_VL QR_NAME(vl)

#ifndef LAMINA_NORMALS_QR_OPS
#define LAMINA_NORMALS_QR_OPS
enum { QR_OP_SUMS, QR_OP_REFLECT };   /* what passes does to the columns */
#endif

static QR_INLINE QR_V QR_NAME(ld)(const double *p)
{
    QR_V v;
    memcpy(&v, p, sizeof v);
    return v;
}

static QR_INLINE void QR_NAME(st)(double *p, QR_V v)
{
    memcpy(p, &v, sizeof v);
}

/* One pass down the rows i = k .. m-1 for G vectors of columns from c0 (a
 * multiple of QR_W): acc gets, lane by lane, the sum over the rows of u_i
 * A_ij (u given) or of A_ij^2, each column's terms added in the row order.
 * Lanes left of the columns asked for (a first vector that starts before
 * them) are summed too and not read by the caller. */
static QR_INLINE void QR_NAME(sums_pass)(int G, int m, int L, int k, int c0, const double *A,
                                         const double *u, double *acc, const double *b,
                                         double *ub)
{
    QR_V s[QR_G];
    for (int g = 0; g < G; g++)
        s[g] = (QR_V){0};
    if (u && b) {
        /* and u . b, its terms in the same order, a chain of its own that
         * runs beside the vectors instead of after them */
        double t = 0;
        for (int i = k; i < m; i++) {
            const double *r = RowAt(A, i, L) + c0;
            double ui = u[i];
            t += ui * b[i];
            for (int g = 0; g < G; g++)
                s[g] += ui * QR_NAME(ld)(r + QR_W * g);
        }
        *ub = t;
    } else if (u)
        for (int i = k; i < m; i++) {
            const double *r = RowAt(A, i, L) + c0;
            double ui = u[i];
            for (int g = 0; g < G; g++)
                s[g] += ui * QR_NAME(ld)(r + QR_W * g);
        }
    else
        for (int i = k; i < m; i++) {
            const double *r = RowAt(A, i, L) + c0;
            for (int g = 0; g < G; g++) {
                QR_V a = QR_NAME(ld)(r + QR_W * g);
                s[g] += a * a;
            }
        }
    for (int g = 0; g < G; g++)
        QR_NAME(st)(acc + c0 + QR_W * g, s[g]);
}

/* One pass of the reflection for G vectors of columns from c0: A_ij -=
 * d_j w_i for i = k .. m-1, and nrm_j = the sum over i = k+1 .. m-1 of the
 * updated A_ij^2 (the sum QR_OP_SUMS would form next, the same terms in the
 * same order, taken while the values are at hand). keep: the lanes of the
 * first vector that must not change (columns left of the reflection's:
 * they hold R), all ones; those keep their bits. */
static QR_INLINE void QR_NAME(reflect_pass)(int G, int m, int L, int k, int c0, double *A,
                                            const double *w, const double *d, double *nrm,
                                            QR_VL keep)
{
    QR_V dv[QR_G], s[QR_G];
    for (int g = 0; g < G; g++) {
        dv[g] = QR_NAME(ld)(d + c0 + QR_W * g);
        s[g] = (QR_V){0};
    }
    /* row k: updated, not in the norms */
    double *rk = RowAt(A, k, L) + c0;
    for (int g = 0; g < G; g++) {
        QR_V a = QR_NAME(ld)(rk + QR_W * g), v = a - dv[g] * w[k];
        if (g == 0)
            v = (QR_V)(((QR_VL)a & keep) | ((QR_VL)v & ~keep));
        QR_NAME(st)(rk + QR_W * g, v);
    }
    for (int i = k + 1; i < m; i++) {
        double *r = RowAt(A, i, L) + c0, wi = w[i];
        for (int g = 0; g < G; g++) {
            QR_V a = QR_NAME(ld)(r + QR_W * g), v = a - dv[g] * wi;
            if (g == 0)
                v = (QR_V)(((QR_VL)a & keep) | ((QR_VL)v & ~keep));
            QR_NAME(st)(r + QR_W * g, v);
            s[g] += v * v;
        }
    }
    for (int g = 0; g < G; g++)
        QR_NAME(st)(nrm + c0 + QR_W * g, s[g]);
}

/* One pass of op for G vectors of columns from c0: QR_OP_SUMS, sums_pass
 * (u, out = acc, b, ub); QR_OP_REFLECT, reflect_pass (u = w, d, out = nrm,
 * keep). op and G are constants where passes calls it, so each call is
 * the one pass it names. */
static QR_INLINE void QR_NAME(pass)(int op, int G, int m, int L, int k, int c0, double *A,
                                    const double *u, const double *d, double *out,
                                    const double *b, double *ub, QR_VL keep)
{
    if (op == QR_OP_SUMS)
        QR_NAME(sums_pass)(G, m, L, k, c0, A, u, out, b, ub);
    else
        QR_NAME(reflect_pass)(G, m, L, k, c0, A, u, d, out, keep);
}

/* op over the columns j0 .. L-1 (and the lanes of j0's vector left of
 * them): QR_G vectors to a pass down the rows, then the rest in one pass,
 * its vector count a constant in each case (the pass's arrays stay in
 * registers). QR_OP_SUMS: out = acc, and with b (u given, j0 <= L) *ub =
 * u . b in the first pass, or alone when no column is left (j0 = L).
 * QR_OP_REFLECT: out = nrm; the lanes of the first vector left of j0 keep
 * their bits (they hold R). */
static QR_INLINE void QR_NAME(passes)(int op, int m, int L, int k, int j0, double *A,
                                      const double *u, const double *d, double *out,
                                      const double *b, double *ub)
{
    int c = j0 & ~(QR_W - 1);
    /* lane l of the first vector is column c + l: kept where left of j0 */
    QR_VL keep = {0}, none = {0};   /* (every lane set below; gcc -O0 cannot see it) */
    for (int l = 0; l < QR_W; l++)
        keep[l] = c + l < j0 ? -1 : 0;
    for (; c + QR_W * QR_G <= L; c += QR_W * QR_G, b = NULL, keep = none)
        QR_NAME(pass)(op, QR_G, m, L, k, c, A, u, d, out, b, ub, keep);
    switch ((L - c) / QR_W) {
#if QR_G > 4
    case 7: QR_NAME(pass)(op, 7, m, L, k, c, A, u, d, out, b, ub, keep); break;
    case 6: QR_NAME(pass)(op, 6, m, L, k, c, A, u, d, out, b, ub, keep); break;
    case 5: QR_NAME(pass)(op, 5, m, L, k, c, A, u, d, out, b, ub, keep); break;
    case 4: QR_NAME(pass)(op, 4, m, L, k, c, A, u, d, out, b, ub, keep); break;
#endif
    case 3: QR_NAME(pass)(op, 3, m, L, k, c, A, u, d, out, b, ub, keep); break;
    case 2: QR_NAME(pass)(op, 2, m, L, k, c, A, u, d, out, b, ub, keep); break;
    case 1: QR_NAME(pass)(op, 1, m, L, k, c, A, u, d, out, b, ub, keep); break;
    default:
        if (op == QR_OP_SUMS && b) {   /* no column left to pass over: u . b alone */
            double t = 0;
            for (int i = k; i < m; i++)
                t += u[i] * b[i];
            *ub = t;
        }
        break;
    }
}

/* The factorisation of the m x L working copy T (columns n .. L-1 zero:
 * lanes being independent, whatever they come to is never read back; so
 * are rows kmax .. m-1 of R's finished columns). w (m), acc and nrm (L
 * each): scratch. */
static QR_INLINE void QR_NAME(factor)(int m, int n, double *T, double *b, int *perm,
                                      double *w, double *acc, double *nrm)
{
    const int L = LM_QR_LD(n);
    int kmax = m < n ? m : n, have_norms = 0;
    for (int k = 0; k < kmax; k++) {
        /* the pivot: the remaining column of largest norm (first of ties);
         * the last reflection has left the norms in nrm */
        if (!have_norms)
            QR_NAME(passes)(QR_OP_SUMS, m, L, k, k, T, NULL, NULL, nrm, NULL, NULL);
        int best = lm_qr_pivot(nrm, k, n);
        if (best != k) {
            for (int i = 0; i < m; i++) {
                double *r = RowAt(T, i, L), t = r[k];
                r[k] = r[best];
                r[best] = t;
            }
            int t = perm[k];
            perm[k] = perm[best];
            perm[best] = t;
        }
        /* column k's rows k .. m-1, contiguous, become the reflection's w,
         * with the sum of the squares below row k (householder()'s, in
         * its order) taken on the way; R's column k below the diagonal is
         * zero (rows kmax .. m-1 are not read again: left as they are) */
        double tail = 0;
        w[k] = RowAt(T, k, L)[k];
        for (int i = k + 1; i < m; i++) {
            double *t = RowAt(T, i, L) + k, x = *t;
            w[i] = x;
            tail += x * x;
            if (i < kmax)
                *t = 0.0;
        }
        double alpha;
        double tau = lm_qr_householder(w + k, tail, &alpha);
        if (tau != 0.0) {
            /* H on the columns right of k and on b: d_j = tau w.c_j, then
             * c_j -= d_j w */
            double db = 0;
            QR_NAME(passes)(QR_OP_SUMS, m, L, k, k + 1, T, w, NULL, acc, b, &db);
            for (int j = k + 1; j < L; j++)
                acc[j] *= tau;
            QR_NAME(passes)(QR_OP_REFLECT, m, L, k, k + 1, T, w, acc, nrm, NULL, NULL);
            db *= tau;
            for (int i = k; i < m; i++)
                b[i] -= db * w[i];
        }
        have_norms = tau != 0.0;
        RowAt(T, k, L)[k] = alpha;
    }
}

#undef QR_V
#undef QR_VL
#undef QR_W
#undef QR_G
#undef QR_NAME
