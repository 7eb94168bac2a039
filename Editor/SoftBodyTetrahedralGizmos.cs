using SoftBodyDynamics.Authoring;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;
using UnityEditor;
using UnityEngine;

namespace SoftBodyDynamics.Editor
{
    /// <summary>
    /// Scene-view preview of a selected mass-spring or FEM body as the baker will build it: mass-spring bodies show their
    /// springs (orange), FEM bodies the edges of their tetrahedra (green). Only for the selected
    /// object, from the cached build, and capped (evenly strided) to keep the Scene view responsive.
    /// </summary>
    static class SoftBodyTetrahedralGizmos
    {
        /// <summary>At most this many springs are drawn.</summary>
        const int k_MaxSpringsDrawn = 8192;
        /// <summary>At most this many tetrahedra are drawn (6 edges each).</summary>
        const int k_MaxTetrahedraDrawn = 2048;

        static readonly Color k_SpringColor = new Color(1f, 0.6f, 0.2f, 0.6f);
        static readonly Color k_TetrahedronColor = new Color(0.3f, 1f, 0.5f, 0.45f);

        [DrawGizmo(GizmoType.Selected | GizmoType.Active)]
        static void DrawSpringsAndTetrahedra(SoftBodyAuthoring authoring, GizmoType gizmoType)
        {
            if (authoring.method != SoftBodyMethod.MassSpring && authoring.method != SoftBodyMethod.Fem)
                return;
            Mesh mesh = SoftBodyAuthoringValidation.FindReadableMesh(authoring, null);
            if (mesh == null || !authoring.Material.IsValid)
                return;
            TetrahedralBodyBuild build = SoftBodyTetrahedralPreviewCache.Build(mesh, authoring.BakedScale, authoring.method,
                authoring.TetrahedralizationSettings, authoring.Material, authoring.MassSpringBuildSettings, authoring.FemBuildSettings).Build;
            if (build == null || !build.Succeeded)
                return;

            // The rest shape already carries the Transform's scale: place it with position and rotation only.
            Matrix4x4 previous = Gizmos.matrix;
            Transform transform = authoring.transform;
            Gizmos.matrix = Matrix4x4.TRS(transform.position, transform.rotation, Vector3.one);
            if (build.Method == SoftBodyMethod.MassSpring)
                DrawSprings(build.MassSpring);
            else
                DrawTetrahedra(build.Tetrahedralization.Mesh);
            Gizmos.matrix = previous;
        }

        static void DrawSprings(MassSpringModelData model)
        {
            int count = model.SpringCount;
            int stride = math.max(1, (count + k_MaxSpringsDrawn - 1) / k_MaxSpringsDrawn);
            Gizmos.color = k_SpringColor;
            for (int s = 0; s < count; s += stride)
            {
                Spring spring = model.Springs[s];
                Gizmos.DrawLine(UnityMathConversions.ToVector3(model.RestPositions[spring.A]), UnityMathConversions.ToVector3(model.RestPositions[spring.B]));
            }
        }

        static void DrawTetrahedra(TetrahedralMesh mesh)
        {
            Gizmos.color = k_TetrahedronColor;
            int count = mesh.TetrahedronCount;
            int stride = math.max(1, (count + k_MaxTetrahedraDrawn - 1) / k_MaxTetrahedraDrawn);
            for (int t = 0; t < count; t += stride)
            {
                int4 n = mesh.Tetrahedra[t];
                Vector3 a = UnityMathConversions.ToVector3(mesh.Positions[n.x]), b = UnityMathConversions.ToVector3(mesh.Positions[n.y]);
                Vector3 c = UnityMathConversions.ToVector3(mesh.Positions[n.z]), d = UnityMathConversions.ToVector3(mesh.Positions[n.w]);
                Gizmos.DrawLine(a, b);
                Gizmos.DrawLine(a, c);
                Gizmos.DrawLine(a, d);
                Gizmos.DrawLine(b, c);
                Gizmos.DrawLine(b, d);
                Gizmos.DrawLine(c, d);
            }
        }
    }
}
