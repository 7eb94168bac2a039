using System.Collections.Generic;
using SoftBodyDynamics.Solvers;

namespace SoftBodyDynamics.Authoring
{
    /// <summary>
    /// Everything validating a <see cref="SoftBodyAuthoring"/> found: the issues in the order they were found
    /// (mesh source, then the builder's, then the solver parameters'), and, when the mesh could be read, the
    /// mesh and the builder's result. The baker bakes <see cref="Result"/> only when <see cref="Succeeded"/>.
    /// </summary>
    public sealed class SoftBodyAuthoringBuild
    {
        public readonly List<SoftBodyIssue> Issues = new List<SoftBodyIssue>();

        /// <summary>The mesh as read; null when there was no readable mesh.</summary>
        public SoftBodyMeshData Mesh;

        /// <summary>The builder's result; null when there was no readable mesh.</summary>
        public SoftBodyBuildResult Result;

        /// <summary>True when the body can be baked: a model was built and no issue is an error.</summary>
        public bool Succeeded => Result != null && Result.Succeeded && !SoftBodyIssue.AnyError(Issues);
    }
}
