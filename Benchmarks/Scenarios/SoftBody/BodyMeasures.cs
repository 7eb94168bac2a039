using System;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>
    /// Whole-body quantities tests and benchmarks assert on, computed in float64 so the measurement
    /// adds no float32 error of its own: momentum, angular momentum, volume ratio, shape error.
    /// </summary>
    public static class BodyMeasures
    {
        /// <summary>P = Σ mᵢ vᵢ (kg·m/s).</summary>
        public static Vector3d Momentum(ReadOnlySpan<float3> v, ReadOnlySpan<float> m)
        {
            Vector3d p = default;
            for (int i = 0; i < v.Length; i++)
                p += m[i] * (Vector3d)v[i];
            return p;
        }

        /// <summary>Σ mᵢ |vᵢ| (kg·m/s): the scale momentum drift is measured against (P itself may be ≈ 0).</summary>
        public static double MomentumScale(ReadOnlySpan<float3> v, ReadOnlySpan<float> m)
        {
            double s = 0;
            for (int i = 0; i < v.Length; i++)
                s += m[i] * ((Vector3d)v[i]).Length;
            return s;
        }

        /// <summary>L = Σ mᵢ (xᵢ − x_cm) × vᵢ about the centre of mass (kg·m²/s).</summary>
        public static Vector3d AngularMomentum(ReadOnlySpan<float3> x, ReadOnlySpan<float3> v, ReadOnlySpan<float> m)
        {
            Vector3d c = Center(x, m);
            Vector3d l = default;
            for (int i = 0; i < x.Length; i++)
                l += m[i] * Vector3d.Cross((Vector3d)x[i] - c, (Vector3d)v[i]);
            return l;
        }

        /// <summary>Mass-weighted centre (m).</summary>
        public static Vector3d Center(ReadOnlySpan<float3> x, ReadOnlySpan<float> m)
        {
            Vector3d c = default;
            double mass = 0;
            for (int i = 0; i < x.Length; i++)
            {
                c += m[i] * (Vector3d)x[i];
                mass += m[i];
            }
            return c / mass;
        }

        /// <summary>
        /// det(A_pq A_qq⁻¹) of the whole body: the volume of the best-fit linear map of the rest shape,
        /// 1 at rest, &lt; 0 when inverted.
        /// </summary>
        public static double VolumeRatio(ReadOnlySpan<float3> x, in ShapeMatchingModel model)
        {
            Moments(x, model, out _, out _, out double[,] apq, out double[,] aqq);
            return Svd3x3Double.Determinant(apq) / Svd3x3Double.Determinant(aqq);
        }

        /// <summary>
        /// RMS distance (m) of the particles from the rest shape placed at its best fit (centre of mass
        /// and the float64 SVD rotation of A_pq): 0 when the body has exactly its rest shape.
        /// </summary>
        public static double ShapeError(ReadOnlySpan<float3> x, in ShapeMatchingModel model)
        {
            Moments(x, model, out Vector3d c, out Vector3d r, out double[,] apq, out _);
            double[,] rot = Svd3x3Double.Decompose(apq).Rotation;
            double sum = 0, mass = 0;
            for (int i = 0; i < x.Length; i++)
            {
                Vector3d q = (Vector3d)model.RestPositions[i] - r;
                Vector3d goal = c + new Vector3d(
                    rot[0, 0] * q.X + rot[0, 1] * q.Y + rot[0, 2] * q.Z,
                    rot[1, 0] * q.X + rot[1, 1] * q.Y + rot[1, 2] * q.Z,
                    rot[2, 0] * q.X + rot[2, 1] * q.Y + rot[2, 2] * q.Z);
                sum += model.Masses[i] * ((Vector3d)x[i] - goal).LengthSquared;
                mass += model.Masses[i];
            }
            return Math.Sqrt(sum / mass);
        }

        /// <summary>Centres of the current (c) and rest (r) shapes, A_pq and A_qq of the whole body, in float64.</summary>
        static void Moments(ReadOnlySpan<float3> x, in ShapeMatchingModel model, out Vector3d c, out Vector3d r,
            out double[,] apq, out double[,] aqq)
        {
            c = Center(x, model.Masses);
            r = Center(model.RestPositions, model.Masses);
            apq = new double[3, 3];
            aqq = new double[3, 3];
            for (int i = 0; i < x.Length; i++)
            {
                Vector3d p = (Vector3d)x[i] - c, q = (Vector3d)model.RestPositions[i] - r;
                for (int a = 0; a < 3; a++)
                for (int b = 0; b < 3; b++)
                {
                    apq[a, b] += model.Masses[i] * p[a] * q[b];
                    aqq[a, b] += model.Masses[i] * q[a] * q[b];
                }
            }
        }

        /// <summary>Largest extent of the rest shape (m): the length errors are measured against.</summary>
        public static double RestSize(in ShapeMatchingModel model)
        {
            float3 lo = model.RestPositions[0], hi = lo;
            foreach (float3 p in model.RestPositions)
            {
                lo = math.min(lo, p);
                hi = math.max(hi, p);
            }
            return math.cmax(hi - lo);
        }
    }

    /// <summary>A float64 3-vector for measurements.</summary>
    public struct Vector3d
    {
        public double X, Y, Z;
        public Vector3d(double x, double y, double z) { X = x; Y = y; Z = z; }
        public static explicit operator Vector3d(float3 v) => new Vector3d(v.x, v.y, v.z);
        public static Vector3d operator +(Vector3d a, Vector3d b) => new Vector3d(a.X + b.X, a.Y + b.Y, a.Z + b.Z);
        public static Vector3d operator -(Vector3d a, Vector3d b) => new Vector3d(a.X - b.X, a.Y - b.Y, a.Z - b.Z);
        public static Vector3d operator *(double s, Vector3d a) => new Vector3d(s * a.X, s * a.Y, s * a.Z);
        public static Vector3d operator /(Vector3d a, double s) => new Vector3d(a.X / s, a.Y / s, a.Z / s);
        public double this[int i] => i == 0 ? X : i == 1 ? Y : Z;
        public double LengthSquared => X * X + Y * Y + Z * Z;
        public double Length => Math.Sqrt(LengthSquared);
        public static double Dot(Vector3d a, Vector3d b) => a.X * b.X + a.Y * b.Y + a.Z * b.Z;
        public static Vector3d operator -(Vector3d a) => new Vector3d(-a.X, -a.Y, -a.Z);
        public static Vector3d Cross(Vector3d a, Vector3d b) =>
            new Vector3d(a.Y * b.Z - a.Z * b.Y, a.Z * b.X - a.X * b.Z, a.X * b.Y - a.Y * b.X);
    }
}
