/* Baseline of bench/simulate_cvode.py: CVODE driving hand-written C right-hand sides.
 *
 * Not project code.  The SUNDIALS declarations and the index type are prepended by the bench
 * script (the same ones dualmech's driver uses), which compiles and links this file against
 * the same SUNDIALS libraries.  The right-hand sides work on CVODE's vectors directly: no
 * copy, no function pointer, no generic solve.
 *
 *   toy car (theta, phi, theta', phi'), p = {g / R}:
 *     theta'' = -phi'^2 sin(theta) cos(theta) - (g/R) sin(theta) cos(phi)
 *     phi''   = (2 sin(theta) theta' phi' - (g/R) sin(phi)) / cos(theta)
 *   (from T = m R^2 (theta'^2 + phi'^2 cos^2 theta) / 2, V = -m g R cos(theta) cos(phi))
 *
 *   3-link chain of point masses, absolute angles from the downward vertical,
 *   p = {W (3 x 3, W_ij = mu_ij l_i l_j, mu_ij = sum_{k >= max(i,j)} m_k), G_i = g l_i mu_ii}:
 *     sum_j W_ij cos(th_i - th_j) th_j'' = -sum_j W_ij sin(th_i - th_j) th_j'^2 - G_i sin(th_i)
 *   solved by Cholesky (the mass matrix is symmetric positive definite).
 */
#include <math.h>

static int toy_car(sunrealtype t, N_Vector y, N_Vector ydot, void *user)
{
    const double *v = N_VGetArrayPointer(y);
    double *d = N_VGetArrayPointer(ydot);
    const double gR = ((const double *)user)[0];
    const double s = sin(v[0]), c = cos(v[0]);
    (void)t;
    d[0] = v[2];
    d[1] = v[3];
    d[2] = -v[3] * v[3] * s * c - gR * s * cos(v[1]);
    d[3] = (2.0 * s * v[2] * v[3] - gR * sin(v[1])) / c;
    return 0;
}

static int chain3(sunrealtype t, N_Vector y, N_Vector ydot, void *user)
{
    const double *v = N_VGetArrayPointer(y);
    double *d = N_VGetArrayPointer(ydot);
    const double *W = (const double *)user, *G = W + 9;
    double M[3][3], f[3], L[3][3] = {{0}}, z[3];
    (void)t;
    for (int i = 0; i < 3; i++) {
        f[i] = -G[i] * sin(v[i]);
        for (int j = 0; j < 3; j++) {
            const double a = v[i] - v[j];
            M[i][j] = W[3 * i + j] * cos(a);
            f[i] -= W[3 * i + j] * sin(a) * v[3 + j] * v[3 + j];
        }
    }
    for (int i = 0; i < 3; i++) {
        for (int j = 0; j <= i; j++) {
            double s = M[i][j];
            for (int k = 0; k < j; k++) s -= L[i][k] * L[j][k];
            L[i][j] = (i == j) ? sqrt(s) : s / L[j][j];
        }
    }
    for (int i = 0; i < 3; i++) {
        double s = f[i];
        for (int k = 0; k < i; k++) s -= L[i][k] * z[k];
        z[i] = s / L[i][i];
    }
    for (int i = 2; i >= 0; i--) {
        double s = z[i];
        for (int k = i + 1; k < 3; k++) s -= L[k][i] * d[3 + k];
        d[3 + i] = s / L[i][i];
    }
    d[0] = v[3]; d[1] = v[4]; d[2] = v[5];
    return 0;
}

/* which: 0 toy car (4 states), 1 3-link chain (6 states); lmm 1 Adams + fixed point,
   2 BDF + Newton with a dense difference-quotient Jacobian; the same settings as dualmech's
   driver.  Returns 0, or the CVODE flag. */
int hand_cvode(int which, double *par, int lmm, double t0, const double *y0, long nout,
               const double *tout, double *yout, double rtol, double atol, long max_steps,
               long *nsteps)
{
    const long n2 = which == 0 ? 4 : 6;
    SUNContext ctx = NULL; void *mem = NULL; N_Vector y = NULL; SUNMatrix A = NULL;
    SUNLinearSolver LS = NULL; SUNNonlinearSolver NLS = NULL;
    double tret = t0;
    int flag = -1000;
    if (SUNContext_Create(0, &ctx) != 0) return flag;
    SUNContext_ClearErrHandlers(ctx);
    y = N_VNew_Serial((sunindextype)n2, ctx);
    mem = CVodeCreate(lmm, ctx);
    memcpy(N_VGetArrayPointer(y), y0, (size_t)n2 * sizeof(double));
    CVodeInit(mem, which == 0 ? toy_car : chain3, t0, y);
    CVodeSetUserData(mem, par);
    CVodeSStolerances(mem, rtol, atol);
    CVodeSetMaxNumSteps(mem, max_steps);
    CVodeSetStopTime(mem, tout[nout - 1]);
    if (lmm == CV_BDF) {
        A = SUNDenseMatrix((sunindextype)n2, (sunindextype)n2, ctx);
        LS = SUNLinSol_Dense(y, A, ctx);
        CVodeSetLinearSolver(mem, LS, A);
    } else {
        NLS = SUNNonlinSol_FixedPoint(y, 0, ctx);
        CVodeSetNonlinearSolver(mem, NLS);
    }
    for (long i = 0; i < nout; i++) {
        flag = CVode(mem, tout[i], y, &tret, CV_NORMAL);
        if (flag < 0) break;
        memcpy(yout + i * n2, N_VGetArrayPointer(y), (size_t)n2 * sizeof(double));
    }
    CVodeGetNumSteps(mem, nsteps);
    CVodeFree(&mem);
    if (LS) SUNLinSolFree(LS);
    if (A) SUNMatDestroy(A);
    if (NLS) SUNNonlinSolFree(NLS);
    N_VDestroy(y);
    SUNContext_Free(&ctx);
    return flag < 0 ? flag : 0;
}
