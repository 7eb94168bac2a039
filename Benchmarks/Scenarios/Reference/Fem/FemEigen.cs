using System;

namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>
    /// The smallest eigenvalue ω² of the linearised vibration problem K(u) φ = ω² M φ about a displacement u (the rest
    /// shape, or a static equilibrium, whose stress stiffening K(u) then includes), with the consistent mass M, by
    /// inverse iteration: K x_{k+1} = M x_k, ω² ≈ x_{k+1}ᵀ M x_k / x_{k+1}ᵀ M x_{k+1} (the Rayleigh quotient of
    /// x_{k+1} when K is symmetric), stopped when ω² changes by less than 1e-12 relatively (≤ 500 iterations).
    /// The error of ω² falls as (ω₁/ω_next)^{2k}; a start vector along <paramref name="start"/> selects the mode
    /// family (e.g. the gravity direction for the bending mode in that plane).
    /// </summary>
    public static class FemEigen
    {
        /// <summary>The lowest ω² (rad²/s²) and its free-dof mode (M-normalised); NaN if K is singular.</summary>
        /// <param name="model">The discretised body.</param>
        /// <param name="u">The displacement (m) to linearise about, every degree of freedom.</param>
        /// <param name="start">The start vector, every degree of freedom (e.g. a body force).</param>
        public static (double OmegaSquared, double[] Mode, int Iterations) Lowest(FemReferenceModel model, double[] u, double[] start)
        {
            int n = model.FreeCount;
            FemCsrMatrix k = model.NewMatrix();
            model.InternalForce(u, new double[model.Mesh.DofCount], k);
            FemCsrMatrix m = model.MassMatrix();
            var solver = new FemBandSolver(n, model.Pattern.Bandwidth);
            if (!solver.Factor(k))
                return (double.NaN, null, 0);
            double[] x = model.Gather(start);
            var mx = new double[n];
            var y = new double[n];
            var my = new double[n];
            m.Multiply(x, mx);
            double lambda = double.NaN;
            int it = 0;
            for (; it < 500; it++)
            {
                solver.Solve(mx, y);
                m.Multiply(y, my);
                double num = 0, den = 0;
                for (int i = 0; i < n; i++)
                {
                    num += y[i] * mx[i];
                    den += y[i] * my[i];
                }
                double next = num / den;
                double s = 1 / Math.Sqrt(den);
                for (int i = 0; i < n; i++)
                {
                    x[i] = y[i] * s;
                    mx[i] = my[i] * s;
                }
                bool done = Math.Abs(next - lambda) <= 1e-12 * Math.Abs(next);
                lambda = next;
                if (done)
                    break;
            }
            return (lambda, x, it + 1);
        }
    }
}
