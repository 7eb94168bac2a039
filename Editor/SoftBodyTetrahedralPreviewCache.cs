using System.Collections.Generic;
using SoftBodyDynamics.Authoring;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;
using UnityEngine;

namespace SoftBodyDynamics.Editor
{
    /// <summary>
    /// The mass-spring and FEM builds per mesh and settings, kept for the inspector's readout and validation and for the
    /// spring and tetrahedron gizmos, so neither rebuilds (tetrahedralises, calibrates, estimates the stable step) on every
    /// repaint. Holds the few most recent builds; a build changes with the mesh (reference or vertex count), the
    /// Transform's scale, the method, the tetrahedralisation settings, the material and the method's build settings.
    /// </summary>
    static class SoftBodyTetrahedralPreviewCache
    {
        const int k_Capacity = 8;

        sealed class Entry
        {
            public Mesh Mesh;
            public int VertexCount;
            public float3 Scale;
            public SoftBodyMethod Method;
            public TetrahedralizationSettings Tetrahedralization;
            public ElasticMaterial Material;
            public bool BendingSprings;
            public FemBuildSettings Fem;
            public SoftBodyMeshData Data;
            public TetrahedralBodyBuild Build;
        }

        // Most recently used last.
        static readonly List<Entry> s_Entries = new List<Entry>();

        /// <summary>A cached <see cref="SoftBodyAuthoringValidation.BuildTetrahedral"/>.</summary>
        public static (SoftBodyMeshData Mesh, TetrahedralBodyBuild Build) Build(Mesh mesh, float3 scale, SoftBodyMethod method,
            in TetrahedralizationSettings tetrahedralization, in ElasticMaterial material, in MassSpringBuildSettings springs,
            in FemBuildSettings fem)
        {
            int vertexCount = mesh.vertexCount;
            for (int i = s_Entries.Count - 1; i >= 0; i--)
            {
                Entry e = s_Entries[i];
                if (!ReferenceEquals(e.Mesh, mesh) || e.VertexCount != vertexCount || !math.all(e.Scale == scale) || e.Method != method
                    || !Same(e.Tetrahedralization, tetrahedralization) || !Same(e.Material, material)
                    || e.BendingSprings != springs.BendingSprings || !e.Fem.SameAs(fem))
                    continue;
                s_Entries.RemoveAt(i);
                s_Entries.Add(e);
                return (e.Data, e.Build);
            }

            (SoftBodyMeshData data, TetrahedralBodyBuild build) = SoftBodyAuthoringValidation.BuildTetrahedral(mesh, scale, method,
                tetrahedralization, material, springs, fem);
            s_Entries.Add(new Entry
            {
                Mesh = mesh, VertexCount = vertexCount, Scale = scale, Method = method, Tetrahedralization = tetrahedralization,
                Material = material, BendingSprings = springs.BendingSprings, Fem = fem, Data = data, Build = build,
            });
            if (s_Entries.Count > k_Capacity)
                s_Entries.RemoveAt(0);
            return (data, build);
        }

        static bool Same(in TetrahedralizationSettings a, in TetrahedralizationSettings b) =>
            a.Resolution == b.Resolution && a.MaxNodes == b.MaxNodes && a.WeldTolerance.Equals(b.WeldTolerance) && a.WeldDistance.Equals(b.WeldDistance);

        static bool Same(in ElasticMaterial a, in ElasticMaterial b) =>
            a.YoungsModulus.Equals(b.YoungsModulus) && a.PoissonRatio.Equals(b.PoissonRatio) && a.Density.Equals(b.Density)
            && a.DampingRatio.Equals(b.DampingRatio);
    }
}
