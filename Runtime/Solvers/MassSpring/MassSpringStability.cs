using System;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// The stable substep of the explicit integrators (symplectic Euler, Verlet). Linearised about the rest shape the
    /// network is M ẍ = −K x − C ẋ, with K = Σ kₑ nₑnₑᵀ blocks and C = Σ cₑ nₑnₑᵀ. A mode of angular frequency ω
    /// under symplectic Euler is stable iff ωh &lt; 2 undamped (Hairer, Lubich &amp; Wanner 2003), and with damping
    /// ratio ζ iff ωh &lt; 2(√(1 + ζ²) − ζ) (Jury's test of λ² − (2 − 2ζωh − ω²h²) λ + 1 − 2ζωh). With
    /// stiffness-proportional damping, ζ = βω/2, this is h &lt; √(β² + 4/ω²) − β. ω_max² is the largest eigenvalue of
    /// M⁻¹K over the free (unpinned) particles, found by power iteration on the symmetric M^{−½} K M^{−½} in double.
    /// Bake time (allocates).
    /// </summary>
    public static class MassSpringStability
    {
        /// <summary>ω_max (rad/s) of the network at rest (springs along their rest directions); pinned particles held.</summary>
        public static double MaxAngularFrequency(in MassSpringModel model, int iterations = 2000, double tolerance = 1e-10)
        {
            int n = model.ParticleCount;
            var scale = new double[n];
            for (int i = 0; i < n; i++)
                scale[i] = model.InverseMasses[i] > 0f ? Math.Sqrt(model.InverseMasses[i]) : 0.0;
            var u = new double[3 * n];
            var y = new double[3 * n];
            var random = new System.Random(12345);
            for (int i = 0; i < 3 * n; i++)
                u[i] = scale[i / 3] > 0.0 ? random.NextDouble() - 0.5 : 0.0;
            double lambda = 0.0;
            for (int it = 0; it < iterations; it++)
            {
                double norm = 0.0;
                for (int i = 0; i < u.Length; i++)
                    norm += u[i] * u[i];
                norm = Math.Sqrt(norm);
                if (!(norm > 0.0))
                    return 0.0;
                for (int i = 0; i < u.Length; i++)
                    u[i] /= norm;
                Apply(model, scale, u, y);
                double rayleigh = 0.0;
                for (int i = 0; i < u.Length; i++)
                    rayleigh += u[i] * y[i];
                (u, y) = (y, u);
                if (it > 10 && Math.Abs(rayleigh - lambda) <= tolerance * Math.Abs(rayleigh))
                {
                    lambda = rayleigh;
                    break;
                }
                lambda = rayleigh;
            }
            return Math.Sqrt(Math.Max(0.0, lambda));
        }

        /// <summary>
        /// Largest substep h (s) at which symplectic Euler and Verlet stay stable: 2/ω_max without damping, else
        /// √(β² + 4/ω_max²) − β with β the largest cₑ/kₑ of the springs (exact for uniform stiffness-proportional damping).
        /// Infinity when no spring is stiff.
        /// </summary>
        public static double MaxStableStep(in MassSpringModel model)
        {
            double omega = MaxAngularFrequency(model);
            if (!(omega > 0.0))
                return double.PositiveInfinity;
            double beta = 0.0;
            foreach (Spring s in model.Springs)
                if (s.Stiffness > 0f)
                    beta = Math.Max(beta, s.Damping / (double)s.Stiffness);
            return Math.Sqrt(beta * beta + 4.0 / (omega * omega)) - beta;
        }

        /// <summary>The warning an inspector shows when substep <paramref name="h"/> (s) exceeds <paramref name="maxStableStep"/> under an explicit integrator; null when it does not.</summary>
        public static ValidationIssue? CheckStep(MassSpringIntegrator integrator, double h, double maxStableStep)
        {
            if (integrator != MassSpringIntegrator.SymplecticEuler && integrator != MassSpringIntegrator.Verlet)
                return null;
            if (h < maxStableStep)
                return null;
            return ValidationIssue.Warning(MassSpringIssueCode.StepAboveStableLimit, -1,
                $"Absurd stiffness for this step: the substep {h * 1e3:G3} ms exceeds the stable limit {maxStableStep * 1e3:G3} ms of {integrator}. " +
                $"Use at least {Math.Ceiling(h / maxStableStep * 1.05)}× the substeps, softer springs, or the ImplicitEuler or Xpbd integrator.");
        }

        /// <summary>y = M^{−½} K M^{−½} u (3-vectors per particle), K from the springs' rest directions.</summary>
        static void Apply(in MassSpringModel model, double[] scale, double[] u, double[] y)
        {
            Array.Clear(y, 0, y.Length);
            foreach (Spring s in model.Springs)
            {
                double dx = (double)model.RestPositions[s.B].x - model.RestPositions[s.A].x;
                double dy = (double)model.RestPositions[s.B].y - model.RestPositions[s.A].y;
                double dz = (double)model.RestPositions[s.B].z - model.RestPositions[s.A].z;
                double l = Math.Sqrt(dx * dx + dy * dy + dz * dz);
                if (!(l > 0.0))
                    continue;
                dx /= l; dy /= l; dz /= l;
                double sa = scale[s.A], sb = scale[s.B];
                int a = 3 * s.A, b = 3 * s.B;
                double along = dx * (sa * u[a] - sb * u[b]) + dy * (sa * u[a + 1] - sb * u[b + 1]) + dz * (sa * u[a + 2] - sb * u[b + 2]);
                double f = s.Stiffness * along;
                y[a] += sa * f * dx; y[a + 1] += sa * f * dy; y[a + 2] += sa * f * dz;
                y[b] -= sb * f * dx; y[b + 1] -= sb * f * dy; y[b + 2] -= sb * f * dz;
            }
        }
    }
}
