using System;
using System.Collections.Generic;

namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>Reference values of the cantilever scene, computed once per setup.</summary>
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

        /// <summary>Where the values come from.</summary>
        public const string Source =
            "References: Euler–Bernoulli with Timoshenko's shear term (κ = 5/6) for the small-load tip, the Euler–Bernoulli first frequency " +
            "(1.8751²/2π)·√(EI/(ρAL⁴)); no large-load reference yet (its error is left out).";

        static readonly Dictionary<MethodBodySetup, CantileverTargets> s_Cache = new Dictionary<MethodBodySetup, CantileverTargets>();

        public static CantileverTargets Get(MethodBodySetup setup)
        {
            if (s_Cache.TryGetValue(setup, out CantileverTargets t))
                return t;
            double e = setup.Material.YoungsModulus, nu = setup.Material.PoissonRatio, rho = setup.Material.Density;
            double l = CantileverScene.Length, h = CantileverScene.Thickness, a = h * h, i = h * h * h * h / 12.0;
            double q = rho * a * 9.81 * CantileverScene.SmallLoad;
            double g = e / (2 * (1 + nu));
            double eb = q * Math.Pow(l, 4) / (8 * e * i);
            t = new CantileverTargets
            {
                SmallTipEulerBernoulli = eb,
                SmallTip = eb + q * l * l / (2 * (5.0 / 6.0) * g * a),
                LargeTip = double.NaN,
                Frequency = 1.8751 * 1.8751 / (2 * Math.PI) * Math.Sqrt(e * i / (rho * a * Math.Pow(l, 4))),
            };
            s_Cache[setup] = t;
            return t;
        }
    }
}
