using System.Collections.Generic;
using SoftBodyDynamics.Authoring;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;
using UnityEngine;

namespace SoftBodyDynamics.Editor
{
    /// <summary>
    /// The builder's result per mesh and build settings, kept for the inspector's readout and validation and
    /// for the particle and cluster gizmos, so neither rebuilds the body on every repaint. Holds the few most
    /// recent builds; a mesh counts as changed when its reference or vertex count changes, and a body's build
    /// changes with its mesh, its Transform's scale (baked into the rest shape) and its Shape settings.
    /// </summary>
    static class SoftBodyBuildPreviewCache
    {
        const int k_Capacity = 16;

        sealed class Entry
        {
            public Mesh Mesh;
            public int VertexCount;
            public float3 Scale;
            public SoftBodyBuildSettings Settings;
            public SoftBodyMeshData Data;
            public SoftBodyBuildResult Result;
        }

        // Most recently used last.
        static readonly List<Entry> s_Entries = new List<Entry>();

        /// <summary>A cached <see cref="SoftBodyAuthoringValidation.Build"/>.</summary>
        public static (SoftBodyMeshData Mesh, SoftBodyBuildResult Result) Build(Mesh mesh, float3 scale, in SoftBodyBuildSettings settings)
        {
            int vertexCount = mesh.vertexCount;
            for (int i = s_Entries.Count - 1; i >= 0; i--)
            {
                Entry entry = s_Entries[i];
                if (!ReferenceEquals(entry.Mesh, mesh) || entry.VertexCount != vertexCount || !math.all(entry.Scale == scale)
                    || !SameSettings(entry.Settings, settings))
                    continue;
                s_Entries.RemoveAt(i);
                s_Entries.Add(entry);
                return (entry.Data, entry.Result);
            }

            (SoftBodyMeshData data, SoftBodyBuildResult result) = SoftBodyAuthoringValidation.Build(mesh, scale, settings);
            s_Entries.Add(new Entry { Mesh = mesh, VertexCount = vertexCount, Scale = scale, Settings = settings, Data = data, Result = result });
            if (s_Entries.Count > k_Capacity)
                s_Entries.RemoveAt(0);
            return (data, result);
        }

        static bool SameSettings(in SoftBodyBuildSettings a, in SoftBodyBuildSettings b) =>
            a.WeldTolerance.Equals(b.WeldTolerance) && a.WeldDistance.Equals(b.WeldDistance)
            && a.AddInteriorParticles == b.AddInteriorParticles && a.InteriorSpacing.Equals(b.InteriorSpacing)
            && a.ClusterSize.Equals(b.ClusterSize) && a.TotalMass.Equals(b.TotalMass)
            && a.BuildQuadratic == b.BuildQuadratic && a.MaxParticles == b.MaxParticles;
    }
}
