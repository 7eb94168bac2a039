using System;
using System.Collections.Generic;
using SoftBodyDynamics.Solvers;

namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>Reference values of the cantilever scene (of the continuum: the same for every mesh), computed once per material.</summary>
    public sealed class CantileverTargets
    {
        /// <summary>Static tip deflection under the small load (m).</summary>
        public double SmallTip;
        /// <summary>Euler–Bernoulli tip deflection under the small load, qL⁴/(8EI) (m).</summary>
        public double SmallTipEulerBernoulli;
        /// <summary>Static tip deflection under the large load (m); NaN when no reference is available.</summary>
        public double LargeTip;
        /// <summary>First bending frequency (Hz).</summary>
        public double Frequency;

        /// <summary>Richardson extrapolation of the float64 reference over these resolutions (Q2 elements across the thickness).</summary>
        public static readonly int[] ReferenceResolutions = { 1, 2, 3 };

        /// <summary>Where the values come from.</summary>
        public const string Source =
            "References: the float64 FEM reference (Q2 hexahedra, Neo-Hookean, Newton statics, inverse iteration for the frequency) at 1, 2 " +
            "and 3 elements across the thickness, Richardson-extrapolated; Euler–Bernoulli qL⁴/(8EI) for the signed small-load column.";

        static readonly Dictionary<(float, float, float), CantileverTargets> s_Cache =
            new Dictionary<(float, float, float), CantileverTargets>();

        /// <summary>Takes <paramref name="targets"/> as the values of <paramref name="material"/>: values an earlier run computed from the same reference sources.</summary>
        public static void Remember(in ElasticMaterial material, CantileverTargets targets)
        {
            lock (s_Cache)
                s_Cache[(material.YoungsModulus, material.PoissonRatio, material.Density)] = targets;
        }

        public static CantileverTargets Get(MethodBodySetup setup)
        {
            lock (s_Cache)
            {
                var key = (setup.Material.YoungsModulus, setup.Material.PoissonRatio, setup.Material.Density);
                if (s_Cache.TryGetValue(key, out CantileverTargets t))
                    return t;
                double e = setup.Material.YoungsModulus, nu = setup.Material.PoissonRatio, rho = setup.Material.Density;
                double l = CantileverScene.Length, h = CantileverScene.Thickness, a = h * h, i = h * h * h * h / 12.0;
                double q = rho * a * 9.81 * CantileverScene.SmallLoad;
                t = new CantileverTargets
                {
                    SmallTipEulerBernoulli = EulerBernoulli.TipDeflectionUnderSelfWeight(q, l, e, i),
                    SmallTip = CantileverReference.TipDeflectionConvergence(l, h, h, e, nu, rho, 9.81 * CantileverScene.SmallLoad,
                        ReferenceResolutions).Estimate.Extrapolated,
                    LargeTip = CantileverReference.TipDeflectionConvergence(l, h, h, e, nu, rho, 9.81 * CantileverScene.LargeLoad,
                        ReferenceResolutions).Estimate.Extrapolated,
                    Frequency = CantileverReference.FrequencyConvergence(l, h, h, e, nu, rho, ReferenceResolutions).Estimate.Extrapolated,
                };
                s_Cache[key] = t;
                return t;
            }
        }
    }
}
