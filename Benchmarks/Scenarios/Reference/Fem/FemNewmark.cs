using System;

namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>
    /// Implicit dynamics M ü + f_int(u) = f_ext by Newmark's average-acceleration rule (β = 1/4, γ = 1/2, the
    /// trapezoidal rule: second order, unconditionally stable and energy conserving for linear problems):
    /// <code>
    ///   a₁ = 4/h² (u₁ − u₀) − 4/h v₀ − a₀        v₁ = v₀ + h/2 (a₀ + a₁)
    ///   r(u₁) = M a₁ + f_int(u₁) − f_ext = 0,  Newton with (K(u₁) + 4/h² M) Δu = −r
    /// </code>
    /// each step converged to ‖r‖₂ ≤ <see cref="Tolerance"/>·max(‖f_ext‖, ‖f_int‖, ‖M a‖) on the free degrees of freedom,
    /// or to a Newton correction below 1e-10 of the step's displacement increment (round-off floor on fine meshes)
    /// (fixed degrees of freedom stay at their values, zero velocity and acceleration). Consistent mass.
    /// Optional stiffness-proportional (Rayleigh) damping of coefficient β: the Kelvin–Voigt viscous force
    /// f_v(u, v) of <see cref="FemReferenceModel.AddViscousForce"/> (β K₀ v at small strain, so a mode of frequency ω has damping
    /// ratio βω/2) joins the residual, r = M a₁ + f_int(u₁) + f_v(u₁, v₁) − f_ext with v₁ = 2/h (u₁ − u₀) − v₀, and
    /// (2/h) C(u₁) joins the Newton matrix (its part through F, of relative size ~ h‖Ḟ‖, is left to the iterations;
    /// the residual, hence the converged step, is exact). The start acceleration solves M a₀ = f_ext − f_int(u₀) − f_v(u₀, v₀).
    /// </summary>
    public sealed class FemNewmark
    {
        /// <summary>Relative residual per step (default 1e-9).</summary>
        public double Tolerance = 1e-9;
        /// <summary>Newton iterations per step before the step is reported unconverged (default 20).</summary>
        public int MaxIterations = 20;
        /// <summary>
        /// Modified Newton (default false): keep the factorisation of K + 2/h C + 4/h² M from earlier iterations and steps,
        /// refactoring only when an iteration reduces the residual by less than <see cref="RefreshRatio"/>. The converged
        /// step is the same to <see cref="Tolerance"/>; each iteration is much cheaper when the factorisation dominates.
        /// </summary>
        public bool ReuseTangent;
        /// <summary>Residual ratio of one iteration above which a reused factorisation is renewed (default 0.25).</summary>
        public double RefreshRatio = 0.25;

        /// <summary>Displacement (m), velocity (m/s), acceleration (m/s²), every degree of freedom.</summary>
        public readonly double[] U, V, A;
        /// <summary>The time step h (s).</summary>
        public readonly double TimeStep;
        /// <summary>Time integrated (s).</summary>
        public double Time { get; private set; }
        /// <summary>Rayleigh coefficient β (s) of the viscous force; 0 = undamped.</summary>
        public readonly double DampingCoefficient;

        readonly FemReferenceModel m_Model;
        readonly FemCsrMatrix m_M, m_K, m_Keff;
        readonly FemBandSolver m_Solver;
        readonly double[] m_Fext, m_Fint, m_R, m_Du, m_Af, m_Ma, m_U0, m_V1;
        bool m_Factored;

        /// <param name="model">The discretised body.</param>
        /// <param name="externalForce">f_ext (N), every degree of freedom, constant in time.</param>
        /// <param name="timeStep">h (s), &gt; 0.</param>
        /// <param name="initialDisplacement">u₀ (m), every degree of freedom, or null for the rest shape.</param>
        /// <param name="initialVelocity">v₀ (m/s), every degree of freedom (zero on fixed ones), or null for rest.</param>
        /// <param name="dampingCoefficient">Rayleigh coefficient β (s) of the viscous force, ≥ 0; 0 = undamped.</param>
        public FemNewmark(FemReferenceModel model, double[] externalForce, double timeStep, double[] initialDisplacement = null,
            double[] initialVelocity = null, double dampingCoefficient = 0)
        {
            if (!(timeStep > 0))
                throw new ArgumentOutOfRangeException(nameof(timeStep));
            if (!(dampingCoefficient >= 0) || double.IsInfinity(dampingCoefficient))
                throw new ArgumentOutOfRangeException(nameof(dampingCoefficient));
            m_Model = model;
            TimeStep = timeStep;
            DampingCoefficient = dampingCoefficient;
            int dofs = model.Mesh.DofCount, n = model.FreeCount;
            U = initialDisplacement != null ? (double[])initialDisplacement.Clone() : new double[dofs];
            V = initialVelocity != null ? (double[])initialVelocity.Clone() : new double[dofs];
            A = new double[dofs];
            m_M = model.MassMatrix();
            m_K = model.NewMatrix();
            m_Keff = model.NewMatrix();
            m_Solver = new FemBandSolver(n, model.Pattern.Bandwidth);
            m_Fext = model.Gather(externalForce);
            m_Fint = new double[dofs];
            m_R = new double[n];
            m_Du = new double[n];
            m_Af = new double[n];
            m_Ma = new double[n];
            m_U0 = new double[n];
            m_V1 = new double[dofs];
            if (double.IsNaN(model.InternalForce(U, m_Fint, null)))
                throw new ArgumentException("The initial displacement has an undefined energy.", nameof(initialDisplacement));
            if (dampingCoefficient > 0)
                model.AddViscousForce(U, V, dampingCoefficient, m_Fint, null, 0);
            for (int k = 0; k < n; k++)
                m_R[k] = m_Fext[k] - m_Fint[model.FreeDofs[k]];
            if (!m_Solver.Factor(m_M))
                throw new InvalidOperationException("Singular mass matrix.");
            m_Solver.Solve(m_R, m_Af);
            for (int k = 0; k < n; k++)
                A[model.FreeDofs[k]] = m_Af[k];
        }

        /// <summary>Advances one step h; returns the Newton report of the step.</summary>
        public FemSolveReport Step()
        {
            FemReferenceModel model = m_Model;
            int n = model.FreeCount;
            int[] free = model.FreeDofs;
            double h = TimeStep, c0 = 4 / (h * h), c1 = 4 / h;
            for (int k = 0; k < n; k++)
                m_U0[k] = U[free[k]];
            // Predictor: the step with a₁ = a₀, u₁ = u₀ + h v₀ + h²/2 a₀.
            for (int k = 0; k < n; k++)
                U[free[k]] += h * V[free[k]] + 0.5 * h * h * A[free[k]];
            var report = new FemSolveReport { Steps = 1 };
            double fextNorm = FemStaticSolver.Norm(m_Fext);
            // Modified Newton (ReuseTangent): the factorisation of an earlier iteration or step stands until the residual
            // falls by less than RefreshRatio in an iteration.
            bool reuse = ReuseTangent && m_Factored, restarted = false;
            double previous = double.PositiveInfinity;
            for (int it = 0; it <= MaxIterations; it++)
            {
                for (int k = 0; k < n; k++)
                    m_Af[k] = c0 * (U[free[k]] - m_U0[k]) - c1 * V[free[k]] - A[free[k]];
                m_M.Multiply(m_Af, m_Ma);
                bool last = it == MaxIterations;
                bool assemble = !last && !reuse;
                double energy = Forces(assemble, h);
                if (double.IsNaN(energy))
                {
                    // A predictor that inverts an element (a large start acceleration, e.g. a sudden release):
                    // start again from u₀ + h v₀, once.
                    if (it > 0 || restarted)
                        break;
                    restarted = true;
                    for (int k = 0; k < n; k++)
                        U[free[k]] = m_U0[k] + h * V[free[k]];
                    it--;
                    continue;
                }
                double fn = 0;
                for (int k = 0; k < n; k++)
                {
                    double fi = m_Fint[free[k]];
                    fn += fi * fi;
                    m_R[k] = m_Ma[k] + fi - m_Fext[k];
                }
                double scale = Math.Max(fextNorm, Math.Max(Math.Sqrt(fn), FemStaticSolver.Norm(m_Ma)));
                report.RelativeResidual = FemStaticSolver.Norm(m_R) / (scale > 0 ? scale : 1);
                if (report.RelativeResidual <= Tolerance)
                {
                    report.Converged = true;
                    break;
                }
                if (last)
                    break;
                if (reuse && report.RelativeResidual > RefreshRatio * previous)
                {
                    // Too slow with the old factorisation: the same forces again, with the tangent.
                    Forces(true, h);
                    assemble = true;
                }
                previous = report.RelativeResidual;
                report.NewtonIterations++;
                if (assemble)
                {
                    m_Keff.SetSum(m_K, c0, m_M);
                    m_Factored = m_Solver.Factor(m_Keff);
                    if (!m_Factored)
                        break;
                    report.Factorizations++;
                    reuse = ReuseTangent;
                }
                m_Solver.Solve(m_R, m_Du);
                double duMax = 0, uMax = 0;
                for (int k = 0; k < n; k++)
                {
                    U[free[k]] -= m_Du[k];
                    duMax = Math.Max(duMax, Math.Abs(m_Du[k]));
                    uMax = Math.Max(uMax, Math.Abs(U[free[k]] - m_U0[k]));
                }
                // Round-off floor: a correction below 1e-10 of this step's displacement increment.
                if (duMax <= 1e-10 * uMax)
                {
                    report.Converged = true;
                    break;
                }
            }
            for (int k = 0; k < n; k++)
            {
                int d = free[k];
                double a1 = c0 * (U[d] - m_U0[k]) - c1 * V[d] - A[d];
                V[d] += 0.5 * h * (A[d] + a1);
                A[d] = a1;
            }
            Time += h;
            return report;
        }

        /// <summary>
        /// f_int(u₁) (+ f_v(u₁, v₁) with v₁ = 2/h (u₁ − u₀) − v₀ when damped) into m_Fint and, when
        /// <paramref name="tangent"/>, K(u₁) (+ 2/h C(u₁)) into m_K; returns the stored energy (NaN: undefined).
        /// </summary>
        double Forces(bool tangent, double h)
        {
            FemReferenceModel model = m_Model;
            int[] free = model.FreeDofs;
            double energy = model.InternalForce(U, m_Fint, tangent ? m_K : null);
            if (double.IsNaN(energy) || !(DampingCoefficient > 0))
                return energy;
            for (int k = 0; k < free.Length; k++)
                m_V1[free[k]] = 2 / h * (U[free[k]] - m_U0[k]) - V[free[k]];
            model.AddViscousForce(U, m_V1, DampingCoefficient, m_Fint, tangent ? m_K : null, 2 / h);
            return energy;
        }

        /// <summary>Kinetic energy ½ vᵀ M v (J), stored energy ∫ Ψ dV (J) and the work potential −f_extᵀ u (J).</summary>
        public (double Kinetic, double Stored, double Potential) Energies()
        {
            FemReferenceModel model = m_Model;
            int n = model.FreeCount;
            double[] v = model.Gather(V);
            var mv = new double[n];
            m_M.Multiply(v, mv);
            double kinetic = 0, potential = 0;
            for (int k = 0; k < n; k++)
            {
                kinetic += 0.5 * v[k] * mv[k];
                potential -= m_Fext[k] * U[model.FreeDofs[k]];
            }
            return (kinetic, model.InternalForce(U, new double[model.Mesh.DofCount], null), potential);
        }
    }
}
