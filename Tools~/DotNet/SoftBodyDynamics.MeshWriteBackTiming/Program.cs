using System;
using System.Diagnostics;
using System.Globalization;
using System.Runtime.InteropServices;
using SoftBodyDynamics.Benchmarks;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Tools.MeshWriteBackTiming
{
    /// <summary>
    /// Times the CPU part of the mesh write-back without Unity: per frame, <see cref="MeshDeformation.Deform"/> for
    /// every body (mesh-space vertices, welded area-weighted normals, bounds), which is what
    /// <c>SoftBodyMeshWriteSystem</c>'s Burst job computes per body, on the shared benchmark sphere
    /// (<see cref="MeshWriteBackBody"/>) at 1, 100 and 1000 bodies. One thread, managed .NET (JIT), not Burst.
    /// Not measured here: the upload (<c>Mesh.SetVertexBufferData</c>), mesh registration with Entities Graphics,
    /// and the ECS overhead around the job; see Documentation~/mesh-write-back.md.
    /// Usage: dotnet run -c Release --project Tools~/DotNet/SoftBodyDynamics.MeshWriteBackTiming [-- --repeats N] [--quick]
    /// Prints one row per body count and a last line "RESULT meshwriteback &lt;passed&gt; &lt;failed&gt;" (a failed
    /// row is a non-finite or out-of-bounds vertex).
    /// </summary>
    static class Program
    {
        const double k_WarmupSeconds = 0.3;
        const int k_MinWarmupFrames = 3;
        /// <summary>Largest displacement of a particle from its placed rest position (m): a visibly deformed body.</summary>
        const float k_Jitter = 0.02f;

        sealed class Body
        {
            public float3[] Particles;
            public float3 Center;
            public quaternion Rotation;
            public DeformedVertex[] Vertices;
            public AxisAlignedBox Bounds;
        }

        static int Main(string[] args)
        {
            int repeats = 15;
            bool quick = false;
            for (int i = 0; i < args.Length; i++)
            {
                if (args[i] == "--quick") quick = true;
                else if (args[i] == "--repeats" && i + 1 < args.Length) repeats = int.Parse(args[++i], CultureInfo.InvariantCulture);
                else
                {
                    Console.Error.WriteLine("usage: SoftBodyDynamics.MeshWriteBackTiming [--repeats N] [--quick]");
                    return 2;
                }
            }
            if (quick) repeats = Math.Min(repeats, 5);

            SoftBodyBuildResult build = MeshWriteBackBody.Build(out float3[] meshVertices, out _, out int[] triangles);
            ShapeMatchingModelData model = build.Model;
            int[] vertexToParticle = build.VertexToParticle;
            int n = model.ParticleCount;
            Console.WriteLine($"machine: {RuntimeInformation.OSDescription}, {Environment.ProcessorCount} logical CPUs, " +
                $"{RuntimeInformation.FrameworkDescription}, {RuntimeInformation.ProcessArchitecture}; one thread, managed (not Burst)");
            Console.WriteLine($"body: UV sphere {MeshWriteBackBody.Segments}x{MeshWriteBackBody.Rings}, {meshVertices.Length} render vertices, " +
                $"{triangles.Length / 3} triangles, {n} particles ({build.SurfaceParticleCount} surface + {build.InteriorParticleCount} interior)");
            Console.WriteLine($"timing: median of {repeats} frames after >= {(quick ? 0.05 : k_WarmupSeconds)} s and >= {k_MinWarmupFrames} frames of warm-up; " +
                "one frame = MeshDeformation.Deform for every body");
            Console.WriteLine();
            Console.WriteLine($"{"bodies",7} {"ms/frame",10} {"min",9} {"max",9} {"us/body",9} {"ns/vertex",10} {"upload MB/frame",16}");

            int passed = 0, failed = 0;
            foreach (int count in MeshWriteBackBody.BodyCounts)
            {
                Body[] bodies = Place(model, count, meshVertices.Length);
                var local = new float3[n];
                var particleNormals = new float3[n];
                double[] ms = Time(() =>
                {
                    foreach (Body b in bodies)
                        b.Bounds = MeshDeformation.Deform(b.Particles, vertexToParticle, triangles, b.Center, b.Rotation,
                            model.BodyRest.RestCenter, local, particleNormals, b.Vertices);
                }, repeats, quick ? 0.05 : k_WarmupSeconds);

                bool ok = Check(bodies, model.BodyRest.RestCenter);
                if (ok) passed++; else failed++;
                double median = ms[ms.Length / 2];
                if (ms.Length % 2 == 0) median = 0.5 * (ms[ms.Length / 2 - 1] + ms[ms.Length / 2]);
                double vertices = (double)count * meshVertices.Length;
                double uploadMb = vertices * Marshal.SizeOf<DeformedVertex>() / 1e6;
                Console.WriteLine(string.Format(CultureInfo.InvariantCulture, "{0,7} {1,10:F3} {2,9:F3} {3,9:F3} {4,9:F2} {5,10:F1} {6,16:F2}{7}",
                    count, median, ms[0], ms[ms.Length - 1], 1000.0 * median / count, 1e6 * median / vertices, uploadMb,
                    ok ? "" : "  FAILED: non-finite or out-of-bounds vertex"));
            }
            Console.WriteLine();
            Console.WriteLine($"RESULT meshwriteback {passed} {failed}");
            return failed == 0 ? 0 : 1;
        }

        /// <summary>
        /// <paramref name="count"/> bodies at <see cref="MeshWriteBackBody.Position"/>, each at a seeded random rotation and
        /// with every particle moved by up to <see cref="k_Jitter"/>, so the normals are not the rest normals. Center and
        /// rotation are the placed rest values (the deformation reads them, it does not fit them).
        /// </summary>
        static Body[] Place(ShapeMatchingModelData model, int count, int vertexCount)
        {
            int n = model.ParticleCount;
            var rng = new Unity.Mathematics.Random(12345u);
            var bodies = new Body[count];
            var velocities = new float3[n];
            var clusters = new ClusterState[model.ClusterCount];
            for (int b = 0; b < count; b++)
            {
                var particles = new float3[n];
                var state = new ShapeMatchingState(particles, velocities, clusters, default, default, default, default);
                ShapeMatchingSolver.Initialize(model.AsModel(), state, MeshWriteBackBody.Position(b), rng.NextQuaternionRotation(),
                    float3.zero, out ParticleBodyStatus status);
                for (int i = 0; i < n; i++)
                    particles[i] += rng.NextFloat3(new float3(-k_Jitter), new float3(k_Jitter));
                bodies[b] = new Body
                {
                    Particles = particles,
                    Center = status.Center,
                    Rotation = status.Rotation,
                    Vertices = new DeformedVertex[vertexCount],
                };
            }
            return bodies;
        }

        /// <summary>Warm-up for at least <paramref name="warmupSeconds"/> and 3 frames, then <paramref name="repeats"/> timed frames, sorted (ms).</summary>
        static double[] Time(Action frame, int repeats, double warmupSeconds)
        {
            var warmup = Stopwatch.StartNew();
            for (int f = 0; f < k_MinWarmupFrames || warmup.Elapsed.TotalSeconds < warmupSeconds; f++)
                frame();
            var ms = new double[repeats];
            for (int r = 0; r < repeats; r++)
            {
                long t0 = Stopwatch.GetTimestamp();
                frame();
                ms[r] = (Stopwatch.GetTimestamp() - t0) * 1000.0 / Stopwatch.Frequency;
            }
            Array.Sort(ms);
            return ms;
        }

        /// <summary>Every vertex finite, inside the sphere's radius plus the jitter around the rest centre, with a unit normal.</summary>
        static bool Check(Body[] bodies, float3 restCenter)
        {
            float limit = MeshWriteBackBody.Radius + 4f * k_Jitter;
            foreach (Body b in bodies)
                foreach (DeformedVertex v in b.Vertices)
                {
                    if (!math.all(math.isfinite(v.Position)) || !math.all(math.isfinite(v.Normal)))
                        return false;
                    if (math.length(v.Position - restCenter) > limit || math.abs(math.length(v.Normal) - 1f) > 1e-3f)
                        return false;
                }
            return true;
        }
    }
}
