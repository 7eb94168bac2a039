using System;
using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>
    /// The explicit (symplectic Euler) stability limit of a finite-element body, for the inspector's warning and for
    /// choosing substeps. A mode of angular frequency ω with stiffness-proportional damping c = βω² is stable under
    /// symplectic Euler iff h² ω² + 2 h β ω² &lt; 4 (Jury's test on its 2×2 update), i.e.
    /// h &lt; √(β² + 4/ω²) − β, which is 2/ω undamped. The fastest mode ω_max of M⁻¹K₀ at rest sets the limit.
    /// Bake-time code (allocates).
    /// </summary>
    public static class FemStability
    {
        /// <summary>
        /// ω_max (rad/s): √ of the largest eigenvalue of M⁻¹K₀ (rest stiffness, pinned nodes fixed), by power iteration
        /// with the Rayleigh quotient xᵀK₀x / xᵀMx. It approaches ω_max from below; <paramref name="iterations"/> = 300
        /// is within 1 % on the meshes of the tests.
        /// </summary>
        public static float MaxFrequency(in FemModel model, int iterations = 300)
        {
            int n = model.ParticleCount;
            var x = new float3[n];
            var y = new float3[n];
            var slots = new float3[model.SlotCount];
            var rotations = new quaternion[model.PointCount];
            Array.Fill(rotations, quaternion.identity);
            var random = new System.Random(12345);
            for (int i = 0; i < n; i++)
                x[i] = model.InverseMasses[i] > 0f
                    ? new float3((float)random.NextDouble() - 0.5f, (float)random.NextDouble() - 0.5f, (float)random.NextDouble() - 0.5f)
                    : float3.zero;
            double rayleigh = 0.0;
            for (int it = 0; it < iterations; it++)
            {
                FemForces.WarpedStiffness(model, rotations, x, slots, 0, model.ElementCount);
                FemForces.Gather(model, slots, y, 0, n);
                double xkx = 0.0, xmx = 0.0;
                float largest = 0f;
                for (int i = 0; i < n; i++)
                {
                    // y = −K₀ x gathered: xᵀK₀x = −x·y; next x = M⁻¹K₀ x.
                    xkx -= math.dot(x[i], y[i]);
                    xmx += model.Masses[i] * math.lengthsq(x[i]);
                    y[i] = -model.InverseMasses[i] * y[i];
                    largest = math.max(largest, math.cmax(math.abs(y[i])));
                }
                if (xmx > 0.0)
                    rayleigh = Math.Max(rayleigh, xkx / xmx);
                if (!(largest > 0f))
                    break;
                for (int i = 0; i < n; i++)
                    x[i] = y[i] / largest;
            }
            return (float)Math.Sqrt(rayleigh);
        }

        /// <summary>
        /// Largest symplectic-Euler substep h (s) of an undamped body: 2/ω_max. The rest stiffness of the stable
        /// Neo-Hookean model equals the co-rotational one (its λ is re-parameterised to match), so both models share it;
        /// a Neo-Hookean body compressed far from rest stiffens and needs a margin.
        /// </summary>
        public static float MaxStableStep(in FemModel model, FemMaterialModel materialModel) => MaxStableStep(MaxFrequency(model), 0f);

        /// <summary>Largest symplectic-Euler substep (s) for ω_max (rad/s) with Rayleigh coefficient β (s): √(β² + 4/ω²) − β.</summary>
        public static float MaxStableStep(float maxFrequency, float dampingCoefficient)
        {
            if (!(maxFrequency > 0f))
                return float.PositiveInfinity;
            double b = math.max(0f, dampingCoefficient), w = maxFrequency;
            return (float)(Math.Sqrt(b * b + 4.0 / (w * w)) - b);
        }
    }
}
