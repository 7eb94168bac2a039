using System;
using System.Collections.Generic;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Tests.Solvers
{
    /// <summary>Box meshes of tetrahedra and a body holding every array a finite-element step needs (tests only).</summary>
    public static class FemTestBodies
    {
        /// <summary>
        /// A box of nx × ny × nz cells spanning [0, size] from the origin, each split into six positively oriented
        /// tetrahedra (<see cref="BoxTetrahedra"/>, Kuhn's split: conforming between cells).
        /// </summary>
        public static TetrahedralMesh Box(int nx, int ny, int nz, float3 size) => BoxTetrahedra.Create(size, new int3(nx, ny, nz), 0.5f * size);

        /// <summary>Bakes <paramref name="mesh"/>; throws when baking reports an error.</summary>
        public static FemModelData Bake(TetrahedralMesh mesh, ElasticMaterial material, bool[] pinned = null,
            FemElementOrder order = FemElementOrder.Linear)
        {
            var issues = new List<ValidationIssue>();
            FemModelData data = FemModelData.Create(mesh, material, pinned ?? Array.Empty<bool>(), issues, order);
            if (data == null)
                throw new InvalidOperationException("Bake failed: " + string.Join("; ", issues));
            return data;
        }
    }

    /// <summary>One finite-element body with its own arrays.</summary>
    public sealed class FemTestBody
    {
        public readonly FemModelData Data;
        public FemParameters Parameters;
        public readonly float3[] Positions, Velocities, ParticleScratch, ElementScratch, WarmStart;
        public readonly quaternion[] Rotations;
        public ParticleBodyStatus Status;

        /// <param name="warmStart">Keep the last implicit substep's Δv as the next solve's first guess (<see cref="FemState.WarmStart"/>).</param>
        public FemTestBody(FemModelData data, FemParameters parameters, float3 position = default, bool warmStart = true)
        {
            Data = data;
            Parameters = parameters;
            int n = data.RestPositions.Length, points = data.AsModel().PointCount;
            Positions = new float3[n];
            Velocities = new float3[n];
            ParticleScratch = new float3[FemState.ScratchPerParticle * n];
            ElementScratch = new float3[FemState.ScratchPerElement * points];
            Rotations = new quaternion[points];
            WarmStart = warmStart ? new float3[n] : Array.Empty<float3>();
            FemSolver.Initialize(Data.AsModel(), State, position, quaternion.identity, float3.zero, out Status);
        }

        public FemState State => FemState.FromScratch(Positions, Velocities, Rotations, ParticleScratch, ElementScratch, WarmStart);

        public FemStepReport Step(float dt, ColliderShape[] colliders = null) =>
            FemSolver.Step(Data.AsModel(), Parameters, colliders ?? Array.Empty<ColliderShape>(), dt, State, ref Status);

        /// <summary>
        /// Mean downward displacement (m) of the nodes of <paramref name="mesh"/> on the face x = <paramref name="tipX"/> from their
        /// rest places about <paramref name="startCenter"/> (the body's centre when it was placed).
        /// </summary>
        public double MeanSag(TetrahedralMesh mesh, float tipX, float3 startCenter)
        {
            double sag = 0;
            int count = 0;
            for (int i = 0; i < mesh.NodeCount; i++)
                if (mesh.Positions[i].x == tipX)
                {
                    sag += (Data.RestPositions[i].y - Data.RestCenter.y + startCenter.y) - Positions[i].y;
                    count++;
                }
            return sag / count;
        }

        /// <summary>Smallest det F over the elements.</summary>
        public float MinDeterminant()
        {
            float min = float.MaxValue;
            foreach (TetElement t in Data.Elements)
            {
                int4 n = t.Nodes;
                min = math.min(min, math.determinant(FemElasticity.DeformationGradient(Positions[n.x], Positions[n.y], Positions[n.z],
                    Positions[n.w], t.InverseRestShape)));
            }
            return min;
        }

        /// <summary>Σ of the elements' current volumes (m³).</summary>
        public float Volume()
        {
            float v = 0f;
            foreach (TetElement t in Data.Elements)
                v += TetrahedralMesh.SignedVolume(Positions[t.Nodes.x], Positions[t.Nodes.y], Positions[t.Nodes.z], Positions[t.Nodes.w]);
            return v;
        }

        /// <summary>Σ mᵢ vᵢ (kg m/s).</summary>
        public double[] Momentum()
        {
            var p = new double[3];
            for (int i = 0; i < Positions.Length; i++)
                for (int a = 0; a < 3; a++)
                    p[a] += (double)Data.Masses[i] * Velocities[i][a];
            return p;
        }

        public bool AllFinite()
        {
            for (int i = 0; i < Positions.Length; i++)
                if (!math.all(math.isfinite(Positions[i])) || !math.all(math.isfinite(Velocities[i])))
                    return false;
            return true;
        }
    }
}
