using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>What <see cref="SquashRecovery.Run"/> measured.</summary>
    public struct SquashRecoveryResult
    {
        /// <summary>Largest |det(A_pq A_qq⁻¹) − 1| of the whole body after any step (dimensionless; 0 = volume kept).</summary>
        public double MaxVolumeError;
        /// <summary>RMS distance from the best-fit rigid placement of the rest shape, over the rest size, at 1 s (dimensionless).</summary>
        public double ShapeErrorAt1s;
        /// <summary>The same at 2 s (dimensionless).</summary>
        public double ShapeErrorAt2s;
        /// <summary>
        /// Largest shape error from 1 s to 2 s (dimensionless): the envelope of the remaining wobble, which a
        /// single sample can miss when it falls near a zero crossing.
        /// </summary>
        public double MaxShapeErrorFrom1sTo2s;
        /// <summary>Steps the NaN guard reset (0 expected).</summary>
        public int Resets;
    }

    /// <summary>
    /// The recovery test: a body at rest is squashed to half its height with x and z stretched by √2 (the
    /// squash keeps its volume, det = 1), released without gravity or colliders, and followed for 2 s.
    /// The reference is the rest shape itself, the exact target of shape matching.
    /// </summary>
    public static class SquashRecovery
    {
        /// <summary>Height factor of the squash; x and z get 1/√factor so the volume is kept.</summary>
        public const float HeightFactor = 0.5f;
        /// <summary>Steps of <see cref="ShapeMatchingBenchmarkBody.TimeStep"/> to 1 s and to 2 s.</summary>
        public const int StepsTo1s = 60, StepsTo2s = 120;

        /// <summary>Squashes the body about its centre of mass (kg·m weighted) and stops every particle.</summary>
        public static void Squash(ShapeMatchingInstance body)
        {
            float3 center = ShapeMatching.CenterOfMass(body.Positions, body.Model.Masses);
            float side = 1f / math.sqrt(HeightFactor);
            var scale = new float3(side, HeightFactor, side);
            for (int i = 0; i < body.Positions.Length; i++)
            {
                body.Positions[i] = center + scale * (body.Positions[i] - center);
                body.Velocities[i] = float3.zero;
            }
            ShapeMatchingSolver.Wake(ref body.Status);
        }

        /// <summary>Runs the test on a fresh instance of <paramref name="model"/> with <paramref name="parameters"/> (gravity is ignored: g = 0).</summary>
        public static SquashRecoveryResult Run(ShapeMatchingModelData model, ShapeMatchingParameters parameters)
        {
            parameters.Acceleration = float3.zero;
            var body = new ShapeMatchingInstance(model, parameters, float3.zero, quaternion.identity);
            ShapeMatchingModel view = model.AsModel();
            double size = BodyMeasures.RestSize(view);
            Squash(body);
            var result = new SquashRecoveryResult();
            for (int step = 1; step <= StepsTo2s; step++)
            {
                ShapeMatchingStepReport report = body.Step(ShapeMatchingBenchmarkBody.TimeStep);
                result.Resets += report.Reset ? 1 : 0;
                double volume = BodyMeasures.VolumeRatio(body.Positions, view);
                result.MaxVolumeError = WorstValue.Max(result.MaxVolumeError, System.Math.Abs(volume - 1.0));
                if (step < StepsTo1s)
                    continue;
                double shape = BodyMeasures.ShapeError(body.Positions, view) / size;
                result.MaxShapeErrorFrom1sTo2s = WorstValue.Max(result.MaxShapeErrorFrom1sTo2s, shape);
                if (step == StepsTo1s)
                    result.ShapeErrorAt1s = shape;
                if (step == StepsTo2s)
                    result.ShapeErrorAt2s = shape;
            }
            return result;
        }
    }
}
