using System;
using Unity.Mathematics;

namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>How far a float32 rotation R, extracted from A, is from the ideal (all measured in float64).</summary>
    public struct RotationError
    {
        /// <summary>|det R − 1|.</summary>
        public double Determinant;
        /// <summary>‖RᵀR − I‖∞ (largest entry).</summary>
        public double Orthonormality;
        /// <summary>‖skew(A Rᵀ)‖_F / ‖A‖_F: zero exactly at a stationary point of tr(RᵀA) (the polar condition).</summary>
        public double SkewResidual;
        /// <summary>(max tr(R'ᵀA) − tr(RᵀA)) / Σσ over proper rotations R': zero at the optimum, ≥ 0 otherwise.</summary>
        public double ObjectiveGap;
        /// <summary>True when every entry of R is finite.</summary>
        public bool Finite;

        public override string ToString() =>
            $"finite {Finite}, |det-1| {Determinant:E2}, orth {Orthonormality:E2}, skew {SkewResidual:E2}, gap {ObjectiveGap:E2}";
    }

    public static class RotationMetrics
    {
        public static RotationError Evaluate(in float3x3 a, in quaternion q)
        {
            var r = new float3x3(q);
            double[,] rd = Svd3x3Double.ToDouble(r);
            double[,] ad = Svd3x3Double.ToDouble(a);
            var e = new RotationError
            {
                Finite = math.all(math.isfinite(r.c0)) && math.all(math.isfinite(r.c1)) && math.all(math.isfinite(r.c2)),
            };
            if (!e.Finite)
            {
                e.Determinant = e.Orthonormality = e.SkewResidual = e.ObjectiveGap = double.PositiveInfinity;
                return e;
            }

            e.Determinant = Math.Abs(Svd3x3Double.Determinant(rd) - 1.0);

            double orth = 0, aNorm = 0, skew = 0;
            for (int i = 0; i < 3; i++)
                for (int j = 0; j < 3; j++)
                {
                    double rtr = 0, arT = 0, arTt = 0;
                    for (int k = 0; k < 3; k++)
                    {
                        rtr += rd[k, i] * rd[k, j];
                        arT += ad[i, k] * rd[j, k];   // (A Rᵀ)_ij
                        arTt += ad[j, k] * rd[i, k];  // (A Rᵀ)_ji
                    }
                    orth = Math.Max(orth, Math.Abs(rtr - (i == j ? 1.0 : 0.0)));
                    aNorm += ad[i, j] * ad[i, j];
                    double s = 0.5 * (arT - arTt);
                    skew += s * s;
                }
            e.Orthonormality = orth;
            e.SkewResidual = aNorm > 0 ? Math.Sqrt(skew / aNorm) : 0.0;

            var svd = Svd3x3Double.Decompose(ad);
            double sum = svd.SigmaSum;
            e.ObjectiveGap = sum > 0 ? (svd.OptimalTrace - Svd3x3Double.Trace(rd, ad)) / sum : 0.0;
            return e;
        }
    }
}
