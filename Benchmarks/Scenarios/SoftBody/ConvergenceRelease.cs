using System;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>
    /// The trajectory-error test: a lattice cube deformed (squashed to <see cref="HeightFactor"/> of its height with
    /// x and z stretched to keep its volume, twisted by <see cref="Twist"/> rad from bottom to top, every particle
    /// jittered by up to ±<see cref="JitterFraction"/> of the spacing, seeded), released at rest without gravity or
    /// colliders and followed for <see cref="Frames"/> frames of <see cref="FrameTime"/>. The solver's positions after
    /// every frame are compared with the float64 RK4 trajectory of the same continuous model from the same float32
    /// start (<see cref="ShapeMatchingContinuousReference"/>); the error is
    /// <code>  e = √( Σ_frames Σᵢ |x_solver − x_ref|² / (frames · N) ) / size</code>
    /// with size the largest rest extent. The deformation keeps every goal strain below the limit of 1 (about 0.3 at
    /// the start), so the model is smooth and RK4 converges at its full order.
    /// </summary>
    public sealed class ConvergenceRelease
    {
        /// <summary>Height factor of the squash; x and z get 1/√factor (volume kept).</summary>
        public const float HeightFactor = 0.8f;
        /// <summary>Twist about the vertical axis from the bottom to the top face (rad).</summary>
        public const float Twist = 0.3f;
        /// <summary>Largest jitter per axis, as a fraction of the lattice spacing.</summary>
        public const float JitterFraction = 0.05f;
        /// <summary>Frame step (s).</summary>
        public const float FrameTime = 1f / 60f;
        /// <summary>Frames followed (1 s).</summary>
        public const int Frames = 60;

        public readonly ShapeMatchingModelData Model;
        public readonly ShapeMatchingParameters Parameters;
        /// <summary>The deformed start (float32, origin zero), the same for the solver and the reference.</summary>
        public readonly float3[] Start;
        /// <summary>Largest rest extent (m), the length errors are divided by.</summary>
        public readonly double Size;

        /// <param name="parameters">Gravity is removed and sleeping switched off.</param>
        public ConvergenceRelease(ShapeMatchingModelData model, ShapeMatchingParameters parameters, float spacing, uint seed)
        {
            Model = model;
            parameters.Body.Acceleration = float3.zero;
            parameters.Body.SleepSpeed = 0f;
            Parameters = parameters;
            Size = BodyMeasures.RestSize(model.AsModel());
            var body = new ShapeMatchingInstance(model, parameters, float3.zero, quaternion.identity);
            Start = (float3[])body.Positions.Clone();
            Deform(Start, model.Masses, spacing, seed);
        }

        /// <summary>The same start with other parameters (e.g. a deliberately wrong frequency); gravity removed, sleeping off.</summary>
        public ConvergenceRelease(ShapeMatchingModelData model, ShapeMatchingParameters parameters, float3[] start)
        {
            Model = model;
            parameters.Body.Acceleration = float3.zero;
            parameters.Body.SleepSpeed = 0f;
            Parameters = parameters;
            Size = BodyMeasures.RestSize(model.AsModel());
            Start = (float3[])start.Clone();
        }

        /// <summary>Squash, twist and jitter about the centre of mass (seeded).</summary>
        public static void Deform(float3[] x, float[] masses, float spacing, uint seed)
        {
            float3 center = ShapeMatching.CenterOfMass(x, masses);
            float top = float.MinValue, bottom = float.MaxValue;
            foreach (float3 p in x)
            {
                top = math.max(top, p.y);
                bottom = math.min(bottom, p.y);
            }
            float side = 1f / math.sqrt(HeightFactor);
            var rng = new Unity.Mathematics.Random(seed);
            for (int i = 0; i < x.Length; i++)
            {
                float3 r = x[i] - center;
                float angle = Twist * ((x[i].y - bottom) / (top - bottom) - 0.5f);
                float c = math.cos(angle), s = math.sin(angle);
                r = new float3(c * r.x - s * r.z, r.y, s * r.x + c * r.z);
                r *= new float3(side, HeightFactor, side);
                x[i] = center + r + (rng.NextFloat3() - 0.5f) * (2f * JitterFraction * spacing);
            }
        }

        /// <summary>World positions after every frame (frames × N) of the solver with <paramref name="substeps"/> substeps per frame.</summary>
        public Vector3d[][] SolverTrajectory(int substeps) => SolverTrajectory(substeps, out _);

        /// <summary>As above; <paramref name="resets"/> counts NaN-guard resets (0 expected).</summary>
        public Vector3d[][] SolverTrajectory(int substeps, out int resets)
        {
            resets = 0;
            var p = Parameters;
            p.Body.Substeps = substeps;
            var body = new ShapeMatchingInstance(Model, p, float3.zero, quaternion.identity);
            Start.CopyTo(body.Positions, 0);
            Array.Clear(body.Velocities, 0, body.Velocities.Length);
            var frames = new Vector3d[Frames][];
            for (int f = 0; f < Frames; f++)
            {
                resets += body.Step(FrameTime).Reset ? 1 : 0;
                frames[f] = World(body);
            }
            return frames;
        }

        /// <summary>The float64 RK4 trajectory with <paramref name="stepsPerFrame"/> steps per frame, sampled after every frame.</summary>
        public Vector3d[][] ReferenceTrajectory(int stepsPerFrame)
        {
            var reference = new ShapeMatchingContinuousReference(Model, Parameters);
            reference.SetState(Start, new float3[Start.Length], float3.zero);
            var frames = new Vector3d[Frames][];
            for (int f = 0; f < Frames; f++)
            {
                reference.Advance(FrameTime, stepsPerFrame);
                frames[f] = (Vector3d[])reference.X.Clone();
            }
            return frames;
        }

        /// <summary>RMS over frames and particles of |a − b|, over <see cref="Size"/>.</summary>
        public double Error(Vector3d[][] a, Vector3d[][] b)
        {
            double sum = 0;
            int count = 0;
            for (int f = 0; f < a.Length; f++)
            for (int i = 0; i < a[f].Length; i++)
            {
                sum += (a[f][i] - b[f][i]).LengthSquared;
                count++;
            }
            return Math.Sqrt(sum / count) / Size;
        }

        /// <summary>Positions of <paramref name="body"/> in world space, float64.</summary>
        public static Vector3d[] World(ShapeMatchingInstance body)
        {
            var o = (Vector3d)body.Status.Origin;
            var x = new Vector3d[body.Positions.Length];
            for (int i = 0; i < x.Length; i++)
                x[i] = o + (Vector3d)body.Positions[i];
            return x;
        }
    }
}
