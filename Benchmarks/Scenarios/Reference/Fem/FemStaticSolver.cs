using System;

namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>What a static or dynamic Newton solve did.</summary>
    public struct FemSolveReport
    {
        /// <summary>True if every load (or time) step met the residual tolerance.</summary>
        public bool Converged;
        /// <summary>Load steps taken (static) or time steps (dynamic).</summary>
        public int Steps;
        /// <summary>Newton iterations over all steps (= tangent factorisations, except in <see cref="FemNewmark.ReuseTangent"/> runs).</summary>
        public int NewtonIterations;
        /// <summary>Tangent factorisations over all steps (counted by <see cref="FemNewmark"/>).</summary>
        public int Factorizations;
        /// <summary>The largest final ‖r‖ / ‖f_ext‖ over the steps (static), or ‖r‖ / ‖ref‖ (dynamic).</summary>
        public double RelativeResidual;
    }

    /// <summary>
    /// Static equilibrium f_int(u) = s f_ext, s: 0 → 1, by Newton's method with load stepping and a backtracking line
    /// search on the total potential Π = W(u) − s f_extᵀu (the loads are conservative): K(u) Δu = −r, u += α Δu, α
    /// halved (≤ 10 times) until Π satisfies Armijo's decrease or the energy is defined again (inverted element). A load step that fails to converge within <see cref="MaxIterations"/>
    /// is halved (≤ 12 times). Converged when ‖r‖₂ ≤ <see cref="Tolerance"/>·‖f_ext‖₂ on the free degrees of freedom, or when
    /// the Newton step is below 1e-13 of the largest displacement (round-off level).
    /// Linear solves are direct (<see cref="FemBandSolver"/>).
    /// </summary>
    public sealed class FemStaticSolver
    {
        /// <summary>Relative residual at convergence (default 1e-10).</summary>
        public double Tolerance = 1e-10;
        /// <summary>Newton iterations per load step before it is halved (default 25).</summary>
        public int MaxIterations = 25;
        /// <summary>Initial number of equal load steps (default 1).</summary>
        public int InitialLoadSteps = 1;

        readonly FemReferenceModel m_Model;
        readonly FemCsrMatrix m_K;
        readonly FemBandSolver m_Solver;

        /// <param name="model">The discretised body.</param>
        public FemStaticSolver(FemReferenceModel model)
        {
            m_Model = model;
            m_K = model.NewMatrix();
            m_Solver = new FemBandSolver(model.FreeCount, model.Pattern.Bandwidth);
        }

        /// <summary>
        /// Solves f_int(u) = f_ext, starting from (and overwriting) <paramref name="u"/> (m, every degree of freedom,
        /// the fixed ones holding their prescribed values, already applied at the start).
        /// </summary>
        /// <param name="u">Displacements (m).</param>
        /// <param name="externalForce">f_ext (N), every degree of freedom (entries on fixed ones are ignored).</param>
        public FemSolveReport Solve(double[] u, double[] externalForce)
        {
            FemReferenceModel model = m_Model;
            int n = model.FreeCount, dofs = model.Mesh.DofCount;
            double[] fext = model.Gather(externalForce);
            double fNorm = Norm(fext);
            var report = new FemSolveReport { Converged = true };
            if (fNorm == 0)
                fNorm = 1;
            var fint = new double[dofs];
            var r = new double[n];
            var du = new double[n];
            var uSave = new double[dofs];
            var trial = new double[dofs];
            double s = 0, ds = 1.0 / Math.Max(1, InitialLoadSteps);
            int halvings = 0;
            while (s < 1)
            {
                double target = Math.Min(1, s + ds);
                Array.Copy(u, uSave, dofs);
                bool ok = false;
                double rel = double.NaN;
                for (int it = 0; it < MaxIterations; it++)
                {
                    double energy = model.InternalForce(u, fint, m_K);
                    if (double.IsNaN(energy))
                        break;
                    for (int k = 0; k < n; k++)
                        r[k] = fint[model.FreeDofs[k]] - target * fext[k];
                    double rn = Norm(r);
                    rel = rn / fNorm;
                    if (rel <= Tolerance)
                    {
                        ok = true;
                        break;
                    }
                    report.NewtonIterations++;
                    if (!m_Solver.Factor(m_K))
                        break;
                    m_Solver.Solve(r, du);
                    // A step below 1e-13 of the displacement: converged to round-off (the residual's floor is set by
                    // the cancellation of element forces of size ~stress × area, which can exceed Tolerance·‖f_ext‖).
                    double duMax = 0, uMax = 0;
                    for (int k = 0; k < n; k++)
                    {
                        duMax = Math.Max(duMax, Math.Abs(du[k]));
                        uMax = Math.Max(uMax, Math.Abs(u[model.FreeDofs[k]]));
                    }
                    if (duMax <= 1e-13 * uMax)
                    {
                        for (int k = 0; k < n; k++)
                            u[model.FreeDofs[k]] -= du[k];
                        ok = true;
                        break;
                    }
                    // Line search on the total potential Π = W(u) − s f_extᵀu along u − α K⁻¹ r (slope −Δuᵀr < 0 for a
                    // positive definite K): Armijo Π(α) ≤ Π(0) − 10⁻⁴ α Δuᵀr, or a change below round-off of W.
                    double pi0 = energy, slope = 0;
                    for (int k = 0; k < n; k++)
                    {
                        pi0 -= target * fext[k] * u[model.FreeDofs[k]];
                        slope += du[k] * r[k];
                    }
                    double alpha = 1;
                    bool accepted = false;
                    for (int ls = 0; ls <= 10 && !accepted; ls++, alpha *= 0.5)
                    {
                        Array.Copy(u, trial, dofs);
                        for (int k = 0; k < n; k++)
                            trial[model.FreeDofs[k]] -= alpha * du[k];
                        double pi = model.InternalForce(trial, fint, null);
                        if (double.IsNaN(pi))
                            continue;
                        for (int k = 0; k < n; k++)
                            pi -= target * fext[k] * trial[model.FreeDofs[k]];
                        accepted = pi <= pi0 - 1e-4 * alpha * Math.Abs(slope) || Math.Abs(pi - pi0) <= 1e-12 * Math.Abs(energy) || ls == 10;
                    }
                    if (!accepted)
                        break;
                    Array.Copy(trial, u, dofs);
                }
                if (ok)
                {
                    s = target;
                    report.Steps++;
                    report.RelativeResidual = Math.Max(report.RelativeResidual, rel);
                    continue;
                }
                Array.Copy(uSave, u, dofs);
                if (++halvings > 12)
                {
                    report.Converged = false;
                    report.RelativeResidual = rel;
                    return report;
                }
                ds *= 0.5;
            }
            return report;
        }

        internal static double Norm(ReadOnlySpan<double> v)
        {
            double s = 0;
            foreach (double x in v)
                s += x * x;
            return Math.Sqrt(s);
        }
    }
}
