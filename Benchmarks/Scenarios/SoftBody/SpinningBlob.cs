using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>What <see cref="SpinningBlob.Run"/> measured.</summary>
    public struct SpinningBlobResult
    {
        /// <summary>Largest |P − P₀| / Σ mᵢ|vᵢ|₀ over the run (dimensionless; 0 = linear momentum kept).</summary>
        public double MaxMomentumDrift;
        /// <summary>Largest |L − L₀| / |L₀| over the run, L about the centre of mass (dimensionless; 0 = angular momentum kept).</summary>
        public double MaxAngularMomentumDrift;
        /// <summary>Steps the NaN guard reset (0 expected).</summary>
        public int Resets;
    }

    /// <summary>
    /// The momentum test: a free body without gravity or colliders, every particle jittered by up to ±20 % of
    /// the spacing, spinning at 3 rad/s about a seeded axis, drifting at 0.5 m/s, with ±0.1 m/s of seeded noise
    /// on every velocity, followed for <see cref="Steps"/> steps. Nothing acts on the body from outside, so P
    /// and L must stay at their initial values; the drift is float32 round-off and any bias of the solver.
    /// </summary>
    public static class SpinningBlob
    {
        /// <summary>Steps of <see cref="ShapeMatchingBenchmarkBody.TimeStep"/> (1000 ≈ 16.7 s).</summary>
        public const int Steps = 1000;
        /// <summary>Spin rate (rad/s).</summary>
        public const float AngularSpeed = 3f;
        /// <summary>Drift speed of the centre of mass (m/s).</summary>
        public const float DriftSpeed = 0.5f;

        /// <summary>Jitters and spins the body (seeded) about its centre of mass.</summary>
        public static void Spin(ShapeMatchingInstance body, float spacing, uint seed)
        {
            var rng = new Random(seed);
            float3 omega = rng.NextFloat3Direction() * AngularSpeed;
            float3 drift = rng.NextFloat3Direction() * DriftSpeed;
            float3 center = ShapeMatching.CenterOfMass(body.Positions, body.Model.Masses);
            for (int i = 0; i < body.Positions.Length; i++)
            {
                body.Positions[i] += (rng.NextFloat3() - 0.5f) * (0.4f * spacing);
                body.Velocities[i] = drift + math.cross(omega, body.Positions[i] - center) + (rng.NextFloat3() - 0.5f) * 0.2f;
            }
            ShapeMatchingSolver.Wake(ref body.Status);
        }

        /// <summary>Runs the test on a fresh instance of <paramref name="model"/> with <paramref name="parameters"/> (g = 0).</summary>
        public static SpinningBlobResult Run(ShapeMatchingModelData model, ShapeMatchingParameters parameters, float spacing, uint seed)
        {
            parameters.Body.Acceleration = float3.zero;
            var body = new ShapeMatchingInstance(model, parameters, float3.zero, quaternion.identity);
            Spin(body, spacing, seed);
            float[] m = model.Masses;
            Vector3d p0 = BodyMeasures.Momentum(body.Velocities, m);
            double scale = BodyMeasures.MomentumScale(body.Velocities, m);
            Vector3d l0 = BodyMeasures.AngularMomentum(body.Positions, body.Velocities, m);
            var result = new SpinningBlobResult();
            for (int step = 0; step < Steps; step++)
            {
                ShapeMatchingStepReport report = body.Step(ShapeMatchingBenchmarkBody.TimeStep);
                result.Resets += report.Reset ? 1 : 0;
                double dp = (BodyMeasures.Momentum(body.Velocities, m) - p0).Length / scale;
                double dl = (BodyMeasures.AngularMomentum(body.Positions, body.Velocities, m) - l0).Length / l0.Length;
                result.MaxMomentumDrift = WorstValue.Max(result.MaxMomentumDrift, dp);
                result.MaxAngularMomentumDrift = WorstValue.Max(result.MaxAngularMomentumDrift, dl);
            }
            return result;
        }
    }
}
