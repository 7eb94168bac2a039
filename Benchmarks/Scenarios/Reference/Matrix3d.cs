using System;

namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>
    /// A float64 3×3 matrix (row-major fields Mrc) for the references: products, inverse, determinant and the
    /// polar rotation. A value type with no allocation, so a reference can evaluate it millions of times.
    /// </summary>
    public readonly struct Matrix3d
    {
        public readonly double M00, M01, M02, M10, M11, M12, M20, M21, M22;

        public Matrix3d(double m00, double m01, double m02, double m10, double m11, double m12, double m20, double m21, double m22)
        {
            M00 = m00; M01 = m01; M02 = m02;
            M10 = m10; M11 = m11; M12 = m12;
            M20 = m20; M21 = m21; M22 = m22;
        }

        public static Matrix3d Identity => new Matrix3d(1, 0, 0, 0, 1, 0, 0, 0, 1);
        public static Matrix3d Zero => default;

        /// <summary>a bᵀ.</summary>
        public static Matrix3d Outer(Vector3d a, Vector3d b) => new Matrix3d(
            a.X * b.X, a.X * b.Y, a.X * b.Z,
            a.Y * b.X, a.Y * b.Y, a.Y * b.Z,
            a.Z * b.X, a.Z * b.Y, a.Z * b.Z);

        public static Matrix3d operator +(in Matrix3d a, in Matrix3d b) => new Matrix3d(
            a.M00 + b.M00, a.M01 + b.M01, a.M02 + b.M02,
            a.M10 + b.M10, a.M11 + b.M11, a.M12 + b.M12,
            a.M20 + b.M20, a.M21 + b.M21, a.M22 + b.M22);

        public static Matrix3d operator -(in Matrix3d a, in Matrix3d b) => new Matrix3d(
            a.M00 - b.M00, a.M01 - b.M01, a.M02 - b.M02,
            a.M10 - b.M10, a.M11 - b.M11, a.M12 - b.M12,
            a.M20 - b.M20, a.M21 - b.M21, a.M22 - b.M22);

        public static Matrix3d operator *(double s, in Matrix3d a) => new Matrix3d(
            s * a.M00, s * a.M01, s * a.M02,
            s * a.M10, s * a.M11, s * a.M12,
            s * a.M20, s * a.M21, s * a.M22);

        public static Matrix3d operator *(in Matrix3d a, in Matrix3d b) => new Matrix3d(
            a.M00 * b.M00 + a.M01 * b.M10 + a.M02 * b.M20, a.M00 * b.M01 + a.M01 * b.M11 + a.M02 * b.M21, a.M00 * b.M02 + a.M01 * b.M12 + a.M02 * b.M22,
            a.M10 * b.M00 + a.M11 * b.M10 + a.M12 * b.M20, a.M10 * b.M01 + a.M11 * b.M11 + a.M12 * b.M21, a.M10 * b.M02 + a.M11 * b.M12 + a.M12 * b.M22,
            a.M20 * b.M00 + a.M21 * b.M10 + a.M22 * b.M20, a.M20 * b.M01 + a.M21 * b.M11 + a.M22 * b.M21, a.M20 * b.M02 + a.M21 * b.M12 + a.M22 * b.M22);

        public static Vector3d operator *(in Matrix3d a, Vector3d v) => new Vector3d(
            a.M00 * v.X + a.M01 * v.Y + a.M02 * v.Z,
            a.M10 * v.X + a.M11 * v.Y + a.M12 * v.Z,
            a.M20 * v.X + a.M21 * v.Y + a.M22 * v.Z);

        public Matrix3d Transpose => new Matrix3d(M00, M10, M20, M01, M11, M21, M02, M12, M22);

        public double Determinant =>
            M00 * (M11 * M22 - M12 * M21) - M01 * (M10 * M22 - M12 * M20) + M02 * (M10 * M21 - M11 * M20);

        /// <summary>The inverse by cofactors (the caller checks the determinant).</summary>
        public Matrix3d Inverse
        {
            get
            {
                double inv = 1.0 / Determinant;
                return new Matrix3d(
                    (M11 * M22 - M12 * M21) * inv, (M02 * M21 - M01 * M22) * inv, (M01 * M12 - M02 * M11) * inv,
                    (M12 * M20 - M10 * M22) * inv, (M00 * M22 - M02 * M20) * inv, (M02 * M10 - M00 * M12) * inv,
                    (M10 * M21 - M11 * M20) * inv, (M01 * M20 - M00 * M21) * inv, (M00 * M11 - M01 * M10) * inv);
            }
        }

        /// <summary>Σ Mᵢⱼ² (the squared Frobenius norm).</summary>
        public double FrobeniusSquared =>
            M00 * M00 + M01 * M01 + M02 * M02 + M10 * M10 + M11 * M11 + M12 * M12 + M20 * M20 + M21 * M21 + M22 * M22;

        /// <summary>Σ aᵢⱼ bᵢⱼ = tr(a bᵀ), the Frobenius inner product.</summary>
        public static double Dot(in Matrix3d a, in Matrix3d b) =>
            a.M00 * b.M00 + a.M01 * b.M01 + a.M02 * b.M02 + a.M10 * b.M10 + a.M11 * b.M11 + a.M12 * b.M12
            + a.M20 * b.M20 + a.M21 * b.M21 + a.M22 * b.M22;

        /// <summary>max |Mᵢⱼ|.</summary>
        public double MaxAbs => Math.Max(Math.Max(Math.Max(Math.Abs(M00), Math.Abs(M01)), Math.Max(Math.Abs(M02), Math.Abs(M10))),
            Math.Max(Math.Max(Math.Abs(M11), Math.Abs(M12)), Math.Max(Math.Max(Math.Abs(M20), Math.Abs(M21)), Math.Abs(M22))));

        public double[,] ToArray() => new[,] { { M00, M01, M02 }, { M10, M11, M12 }, { M20, M21, M22 } };

        public static Matrix3d FromArray(double[,] m) =>
            new Matrix3d(m[0, 0], m[0, 1], m[0, 2], m[1, 0], m[1, 1], m[1, 2], m[2, 0], m[2, 1], m[2, 2]);

        /// <summary>
        /// The proper rotation closest to the matrix (its polar factor when det &gt; 0), by Higham's Newton iteration
        /// with determinant scaling, X ← ½(γX + γ⁻¹X⁻ᵀ), γ = |det X|^(−1/3), to float64 round-off (quadratic
        /// convergence, 6–10 iterations). A method independent of the solver's quaternion iteration. A singular or
        /// inverted matrix (det ≤ 0) takes the sign-corrected SVD rotation of <see cref="Svd3x3Double"/> instead.
        /// </summary>
        public Matrix3d PolarRotation()
        {
            double scale = MaxAbs;
            if (!(scale > 0.0) || double.IsInfinity(scale))
                return Identity;
            Matrix3d x = (1.0 / scale) * this;
            if (!(x.Determinant > 1e-12))
                return FromArray(Svd3x3Double.Decompose(ToArray()).Rotation);
            for (int k = 0; k < 60; k++)
            {
                double det = x.Determinant;
                double gamma = Math.Pow(Math.Abs(det), -1.0 / 3.0);
                Matrix3d next = 0.5 * (gamma * x + (1.0 / gamma) * x.Inverse.Transpose);
                double change = (next - x).FrobeniusSquared;
                x = next;
                if (change <= 1e-30 * x.FrobeniusSquared)
                    break;
            }
            return x;
        }
    }
}
