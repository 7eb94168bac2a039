using System.Collections.Generic;
using SoftBodyDynamics.Solvers;

namespace SoftBodyDynamics.Authoring
{
    /// <summary>
    /// Everything validating a <see cref="SoftBodyAuthoring"/> found: the issues in the order they were found
    /// (mesh source, then the builder's, then the solver parameters'), and, when the mesh could be read, the
    /// mesh and the builder's result: <see cref="Result"/> for shape matching, <see cref="Tetrahedral"/> for the
    /// mass-spring and FEM methods. The baker bakes only when <see cref="Succeeded"/>.
    /// </summary>
    public sealed class SoftBodyAuthoringBuild
    {
        public readonly List<ValidationIssue> Issues = new List<ValidationIssue>();

        /// <summary>The mesh as read; null when there was no readable mesh.</summary>
        public SoftBodyMeshData Mesh;

        /// <summary>The method the body was validated for.</summary>
        public SoftBodyMethod Method;

        /// <summary>The shape-matching builder's result; null when there was no readable mesh or the method is another.</summary>
        public SoftBodyBuildResult Result;

        /// <summary>The mass-spring or FEM build; null when there was no readable mesh, the material is invalid, or the method is shape matching.</summary>
        public TetrahedralBodyBuild Tetrahedral;

        /// <summary>True when the body can be baked: the method's model was built and no issue is an error.</summary>
        public bool Succeeded => !ValidationIssue.AnyError(Issues) && (Method == SoftBodyMethod.ShapeMatching
            ? Result != null && Result.Succeeded
            : Tetrahedral != null && Tetrahedral.Succeeded);
    }
}
