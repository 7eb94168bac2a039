using System;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>
    /// What the squash-and-release scene reads from a sampled release, the same estimators for every method and for the
    /// float64 reference (sampled at the same instants), so that a method that reproduced the reference's motion would
    /// score zero error whatever the sampling.
    /// <list type="bullet">
    /// <item>Amplitude A = √(X² + (V/ω₁)²) / L: X the RMS displacement from the rest shape and V the RMS velocity over the
    /// body's volume, both after removing the rigid motion, ω₁ the lowest excited mode of the cube. For one damped mode it is the
    /// mode's amplitude and never increases (with ä = −ω²a − 2ζωȧ, d/dt(a² + ȧ²/ω²) = −4ζ ȧ²/ω ≤ 0), unlike X alone, which touches zero twice a
    /// period.</item>
    /// <item>Recovery time: the last downward crossing of the threshold by A, interpolated log-linearly between the samples
    /// around it. Since A decays smoothly, the time moves continuously with the motion; the last crossing of X itself
    /// would jump by half a period when a peak of X passes the threshold. A's ripple (relative ζ/2 at twice the mode's
    /// frequency) bounds the interpolation's miss by ωΔt²/4: 1.4 ms for the cube at 60 Hz, 0.2 % of its recovery time.</item>
    /// <item>Overshoot: the largest height after the first upward crossing of the rest height, minus the rest height, over
    /// the squash (rest − squashed height); the peak from the parabola through the largest sample and its neighbours.</item>
    /// </list>
    /// </summary>
    public static class SquashMeasures
    {
        /// <summary>A = √(X² + (V/ω)²) / L for RMS displacement X (m), RMS speed V (m/s), ω (rad/s), size L (m).</summary>
        public static double Amplitude(double displacement, double speed, double omega, double size) =>
            Math.Sqrt(displacement * displacement + speed / omega * (speed / omega)) / size;

        /// <summary>
        /// Time (s, from sample 0) after which <paramref name="amplitude"/> stays at or below <paramref name="threshold"/>:
        /// the last downward crossing, log-linear between samples; 0 if no sample is above; +∞ if the last sample is above;
        /// NaN if a sample is not finite.
        /// </summary>
        /// <param name="amplitude">Samples, equally spaced.</param>
        /// <param name="interval">Sample spacing (s).</param>
        /// <param name="threshold">Threshold (&gt; 0).</param>
        public static double RecoveryTime(ReadOnlySpan<double> amplitude, double interval, double threshold)
        {
            int last = -1;
            for (int k = 0; k < amplitude.Length; k++)
            {
                if (!double.IsFinite(amplitude[k]))
                    return double.NaN;
                if (amplitude[k] > threshold)
                    last = k;
            }
            if (last < 0)
                return 0;
            if (last == amplitude.Length - 1)
                return double.PositiveInfinity;
            double a = amplitude[last], b = amplitude[last + 1];
            double fraction = b > 0 ? Math.Log(a / threshold) / Math.Log(a / b) : 0;
            return (last + fraction) * interval;
        }

        /// <summary>
        /// (H_max − H_rest) / (H_rest − H_squashed), H_max the largest <paramref name="height"/> from the first sample at or
        /// above <paramref name="restHeight"/> on (parabolic peak through its neighbours); 0 if the height never reaches
        /// the rest height; NaN if a sample is not finite.
        /// </summary>
        public static double Overshoot(ReadOnlySpan<double> height, double restHeight, double squashedHeight)
        {
            int first = -1;
            for (int k = 0; k < height.Length; k++)
            {
                if (!double.IsFinite(height[k]))
                    return double.NaN;
                if (first < 0 && height[k] >= restHeight)
                    first = k;
            }
            if (first < 0)
                return 0;
            int top = first;
            for (int k = first; k < height.Length; k++)
                if (height[k] > height[top])
                    top = k;
            double peak = height[top];
            if (top > 0 && top < height.Length - 1)
            {
                // Parabola through (−1, h₀), (0, h₁), (1, h₂): vertex h₁ − (h₂ − h₀)² / (8 (h₀ − 2h₁ + h₂)) when it opens down.
                double h0 = height[top - 1], h1 = height[top], h2 = height[top + 1];
                double curvature = h0 - 2 * h1 + h2;
                if (curvature < 0)
                    peak = h1 - (h2 - h0) * (h2 - h0) / (8 * curvature);
            }
            return Math.Max(0, peak - restHeight) / (restHeight - squashedHeight);
        }

        /// <summary>
        /// RMS displacement X (m) from the rest shape and RMS velocity V (m/s) over the body's volume, after removing the
        /// rigid motion: the translation of the centre of mass, the rotation that best fits the rest shape to the positions
        /// (the rotational part of Σ mᵢ (xᵢ − c)(Xᵢ − X_c)ᵀ) and the velocity of the centre plus the angular velocity I⁻¹ L.
        /// The integrals are exact for the piecewise-linear fields of the tetrahedra (the consistent-mass rule
        /// ∫_t |d|² dV = V_t/20 (Σ_a |d_a|² + |Σ_a d_a|²)), so a coarse mesh is not read as more deformed than a fine one.
        /// </summary>
        public static void Deformation(IMethodBody body, TetrahedralMesh mesh, out double displacement, out double speed)
        {
            float3[] x = body.Positions, v = body.Velocities, rest = body.RestPositions;
            float[] m = body.Masses;
            RigidFrame frame = RigidFrame.Of(x, m);
            RigidFrame restFrame = RigidFrame.Of(rest, m);
            float3x3 apq = float3x3.zero;
            float3 momentum = float3.zero, angular = float3.zero;
            for (int i = 0; i < x.Length; i++)
            {
                float3 p = x[i] - frame.Center;
                apq += m[i] * Matrix3.Outer(p, rest[i] - restFrame.Center);
                momentum += m[i] * v[i];
                angular += m[i] * math.cross(p, v[i]);
            }
            quaternion q = quaternion.identity;
            RotationExtraction.Extract(apq, ref q);
            float3x3 r = new float3x3(q);
            float3 centerVelocity = momentum / frame.Mass;
            // Σ mᵢ (xᵢ − c) = 0, so Σ mᵢ (xᵢ − c) × vᵢ is the angular momentum about the centre.
            float3 omega = math.mul(frame.InverseInertia, angular);
            var d = new double[3 * x.Length];
            var w = new double[3 * x.Length];
            for (int i = 0; i < x.Length; i++)
            {
                float3 p = x[i] - frame.Center;
                float3 fit = math.mul(r, rest[i] - restFrame.Center), rigid = centerVelocity + math.cross(omega, p);
                for (int c = 0; c < 3; c++)
                {
                    d[3 * i + c] = (double)p[c] - fit[c];
                    w[3 * i + c] = (double)v[i][c] - rigid[c];
                }
            }
            double volume = 0, xx = 0, vv = 0;
            foreach (int4 t in mesh.Tetrahedra)
            {
                double vt = Math.Abs(TetrahedralMesh.SignedVolume(mesh.Positions[t.x], mesh.Positions[t.y], mesh.Positions[t.z], mesh.Positions[t.w]));
                volume += vt;
                xx += vt / 20 * Quadratic(d, t);
                vv += vt / 20 * Quadratic(w, t);
            }
            displacement = Math.Sqrt(xx / volume);
            speed = Math.Sqrt(vv / volume);
        }

        /// <summary>Σ_a |f_a|² + |Σ_a f_a|² over the corners of <paramref name="t"/>.</summary>
        static double Quadratic(double[] f, int4 t)
        {
            double squares = 0, sum = 0;
            for (int c = 0; c < 3; c++)
            {
                double a = f[3 * t.x + c], b = f[3 * t.y + c], e = f[3 * t.z + c], g = f[3 * t.w + c];
                squares += a * a + b * b + e * e + g * g;
                sum += (a + b + e + g) * (a + b + e + g);
            }
            return squares + sum;
        }

        /// <summary>
        /// ∫N_a dA per node over the boundary triangles lying in the plane y = <paramref name="y"/> at rest (area/3 to each
        /// corner of each such tetrahedron face), zero off it: the exact weights of the piecewise-linear face field.
        /// </summary>
        public static double[] FaceWeights(TetrahedralMesh mesh, float y, float tolerance)
        {
            var weights = new double[mesh.NodeCount];
            Span<int> corners = stackalloc int[4];
            foreach (int4 t in mesh.Tetrahedra)
            {
                corners[0] = t.x; corners[1] = t.y; corners[2] = t.z; corners[3] = t.w;
                for (int skip = 0; skip < 4; skip++)
                {
                    int a = corners[(skip + 1) & 3], b = corners[(skip + 2) & 3], c = corners[(skip + 3) & 3];
                    float3 pa = mesh.Positions[a], pb = mesh.Positions[b], pc = mesh.Positions[c];
                    if (Math.Abs(pa.y - y) > tolerance || Math.Abs(pb.y - y) > tolerance || Math.Abs(pc.y - y) > tolerance)
                        continue;
                    double third = 0.5 * math.length(math.cross(pb - pa, pc - pa)) / 3;
                    weights[a] += third;
                    weights[b] += third;
                    weights[c] += third;
                }
            }
            return weights;
        }

        /// <summary>
        /// Distance (m) between the <paramref name="top"/>- and <paramref name="bottom"/>-weighted centroids of <paramref name="x"/>
        /// (weights per mesh node; a body's extra nodes after them, as quadratic elements' edge nodes, weigh nothing).
        /// </summary>
        public static double Height(ReadOnlySpan<float3> x, double[] top, double[] bottom)
        {
            double tx = 0, ty = 0, tz = 0, bx = 0, by = 0, bz = 0, tw = 0, bw = 0;
            for (int i = 0; i < top.Length; i++)
            {
                tx += top[i] * x[i].x; ty += top[i] * x[i].y; tz += top[i] * x[i].z; tw += top[i];
                bx += bottom[i] * x[i].x; by += bottom[i] * x[i].y; bz += bottom[i] * x[i].z; bw += bottom[i];
            }
            double dx = tx / tw - bx / bw, dy = ty / tw - by / bw, dz = tz / tw - bz / bw;
            return Math.Sqrt(dx * dx + dy * dy + dz * dz);
        }
    }
}
