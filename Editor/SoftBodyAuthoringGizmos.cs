using SoftBodyDynamics.Authoring;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;
using UnityEditor;
using UnityEngine;

namespace SoftBodyDynamics.Editor
{
    /// <summary>
    /// Scene-view preview of a selected soft body as the baker will build it: particles as small spheres
    /// (surface cyan, interior yellow) and each cluster's rest bounds as a green wire box. Uses the cached
    /// build, so it costs one build per change of mesh or Shape settings.
    /// </summary>
    static class SoftBodyAuthoringGizmos
    {
        /// <summary>At most this many particles are drawn (evenly strided) to keep the Scene view responsive.</summary>
        const int k_MaxParticlesDrawn = 4096;
        /// <summary>At most this many cluster boxes are drawn.</summary>
        const int k_MaxClustersDrawn = 512;

        static readonly Color k_SurfaceColor = new Color(0.2f, 0.9f, 1f, 0.9f);
        static readonly Color k_InteriorColor = new Color(1f, 0.85f, 0.2f, 0.9f);
        static readonly Color k_ClusterColor = new Color(0.3f, 1f, 0.4f, 0.35f);

        [DrawGizmo(GizmoType.Selected | GizmoType.Active)]
        static void DrawParticlesAndClusters(SoftBodyAuthoring authoring, GizmoType gizmoType)
        {
            if (authoring.method != SoftBodyMethod.ShapeMatching)
                return; // SoftBodyTetrahedralGizmos draws the other methods.
            Mesh mesh = SoftBodyAuthoringValidation.FindReadableMesh(authoring, null);
            if (mesh == null)
                return;
            SoftBodyBuildResult result = SoftBodyBuildPreviewCache.Build(mesh, authoring.BakedScale, authoring.BuildSettings).Result;
            if (result == null || !result.Succeeded)
                return;

            // The rest shape already carries the Transform's scale: place it with position and rotation only.
            Matrix4x4 previous = Gizmos.matrix;
            Transform transform = authoring.transform;
            Gizmos.matrix = Matrix4x4.TRS(transform.position, transform.rotation, Vector3.one);
            DrawParticles(result, authoring.particleRadius);
            DrawClusters(result.Model);
            Gizmos.matrix = previous;
        }

        static void DrawParticles(SoftBodyBuildResult result, float radius)
        {
            float3[] positions = result.Model.RestPositions;
            int stride = math.max(1, (positions.Length + k_MaxParticlesDrawn - 1) / k_MaxParticlesDrawn);
            for (int i = 0; i < positions.Length; i += stride)
            {
                Gizmos.color = i < result.SurfaceParticleCount ? k_SurfaceColor : k_InteriorColor;
                Gizmos.DrawSphere(UnityMathConversions.ToVector3(positions[i]), radius);
            }
        }

        static void DrawClusters(ShapeMatchingModelData model)
        {
            Gizmos.color = k_ClusterColor;
            int clusters = model.ClusterCount;
            int stride = math.max(1, (clusters + k_MaxClustersDrawn - 1) / k_MaxClustersDrawn);
            for (int c = 0; c < clusters; c += stride)
            {
                int start = model.ClusterOffsets[c], end = model.ClusterOffsets[c + 1];
                if (end <= start)
                    continue;
                float3 min = model.RestPositions[model.ClusterParticles[start]], max = min;
                for (int k = start + 1; k < end; k++)
                {
                    float3 p = model.RestPositions[model.ClusterParticles[k]];
                    min = math.min(min, p);
                    max = math.max(max, p);
                }
                Gizmos.DrawWireCube(UnityMathConversions.ToVector3(0.5f * (min + max)), UnityMathConversions.ToVector3(max - min));
            }
        }
    }
}
