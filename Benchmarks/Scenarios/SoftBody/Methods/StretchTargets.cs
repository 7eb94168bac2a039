using System;
using System.Collections.Generic;
using SoftBodyDynamics.Solvers;

namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>
    /// Reference extensions of the stretch scene (of the continuum: the same for every mesh), one per load of
    /// <see cref="StretchScene.Loads"/>, computed once per material.
    /// </summary>
    public sealed class StretchTargets
    {
        /// <summary>The clamped bar's extension per load (m): the float64 FEM reference, Richardson-extrapolated when computed at three or more resolutions.</summary>
        public double[] Extensions;
        /// <summary>The reference's extension per load and resolution (m), [load][resolution].</summary>
        public double[][] ExtensionsPerResolution;
        /// <summary>Observed order of the reference's mesh convergence per load (NaN with fewer than three resolutions).</summary>
        public double[] Orders;
        /// <summary>Resolutions of the reference (Q2 elements across the section).</summary>
        public int[] Resolutions;
        /// <summary>The uniform-section (slender-bar) Neo-Hookean extension per load (m), <see cref="HangingBarReference.UniformSectionExtension"/>.</summary>
        public double[] UniformSection;
        /// <summary>The linear bar's extension ρ g L² / (2E) per load (m).</summary>
        public double[] Linear;
        /// <summary>The estimated bound on the clamp's end effect per load, <see cref="HangingBarReference.EndEffectBound"/> (fraction).</summary>
        public double[] EndEffectBound;

        /// <summary>Richardson extrapolation of the float64 reference over these resolutions (Q2 elements across the section).</summary>
        public static readonly int[] ReferenceResolutions = { 1, 2, 3 };

        /// <summary>Where the values come from.</summary>
        public const string Source =
            "Reference: the float64 FEM of the same clamped bar (Q2 hexahedra, compressible Neo-Hookean, Newton statics with the body " +
            "force, each load continued from the previous one) at 1, 2 and 3 elements across, Richardson-extrapolated per load; " +
            "checked against the uniform-section Neo-Hookean curve δ = ∫₀ᴸ (λ(ρg(L − X)) − 1) dX (the slender-bar answer: every section in uniaxial tension with free sides, the clamp's included).";

        static readonly Dictionary<(float, float, float), StretchTargets> s_Cache = new Dictionary<(float, float, float), StretchTargets>();

        /// <summary>Takes <paramref name="targets"/> as the values of <paramref name="material"/>: values an earlier run computed from the same reference sources.</summary>
        public static void Remember(in ElasticMaterial material, StretchTargets targets)
        {
            lock (s_Cache)
                s_Cache[(material.YoungsModulus, material.PoissonRatio, material.Density)] = targets;
        }

        /// <summary>The targets of <paramref name="material"/> at <see cref="ReferenceResolutions"/>, computed once (about 10–30 s).</summary>
        public static StretchTargets Get(in ElasticMaterial material)
        {
            lock (s_Cache)
            {
                var key = (material.YoungsModulus, material.PoissonRatio, material.Density);
                if (!s_Cache.TryGetValue(key, out StretchTargets t))
                    s_Cache[key] = t = Compute(material, ReferenceResolutions);
                return t;
            }
        }

        /// <summary>
        /// The targets at <paramref name="resolutions"/> (ascending): Richardson-extrapolated with three or more, else the
        /// finest value (a cheaper, less accurate reference for tests). Not cached.
        /// </summary>
        public static StretchTargets Compute(in ElasticMaterial material, int[] resolutions)
        {
            double e = material.YoungsModulus, nu = material.PoissonRatio, rho = material.Density;
            double l = StretchScene.Length, h = StretchScene.Thickness;
            int loads = StretchScene.Loads.Length;
            var g = new double[loads];
            for (int k = 0; k < loads; k++)
                g[k] = StretchScene.Gravity * StretchScene.Loads[k];
            var t = new StretchTargets
            {
                Extensions = new double[loads],
                ExtensionsPerResolution = new double[loads][],
                Orders = new double[loads],
                Resolutions = resolutions,
                UniformSection = new double[loads],
                Linear = new double[loads],
                EndEffectBound = new double[loads],
            };
            if (resolutions.Length >= 3)
            {
                MeshConvergenceResult[] c = HangingBarReference.ExtensionConvergence(l, h, e, nu, rho, g, resolutions);
                for (int k = 0; k < loads; k++)
                {
                    t.ExtensionsPerResolution[k] = c[k].Values;
                    t.Extensions[k] = c[k].Estimate.Extrapolated;
                    t.Orders[k] = c[k].Estimate.Order;
                }
            }
            else
            {
                for (int k = 0; k < loads; k++)
                    t.ExtensionsPerResolution[k] = new double[resolutions.Length];
                for (int i = 0; i < resolutions.Length; i++)
                {
                    HangingBarResult r = HangingBarReference.Extensions(l, h, e, nu, rho, g, resolutions[i]);
                    if (!r.Converged)
                        throw new InvalidOperationException($"The hanging-bar reference did not converge at resolution {resolutions[i]}.");
                    for (int k = 0; k < loads; k++)
                        t.ExtensionsPerResolution[k][i] = r.Extensions[k];
                }
                for (int k = 0; k < loads; k++)
                {
                    t.Extensions[k] = t.ExtensionsPerResolution[k][resolutions.Length - 1];
                    t.Orders[k] = double.NaN;
                }
            }
            for (int k = 0; k < loads; k++)
            {
                t.UniformSection[k] = HangingBarReference.UniformSectionExtension(l, e, nu, rho, g[k]);
                t.Linear[k] = HangingBarReference.LinearExtension(l, e, rho, g[k]);
                t.EndEffectBound[k] = HangingBarReference.EndEffectBound(l, h, e, nu, rho, g[k]);
            }
            return t;
        }
    }
}
