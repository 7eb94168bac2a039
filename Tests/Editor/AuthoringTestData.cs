using System.Collections.Generic;
using SoftBodyDynamics.Solvers;
using UnityEngine;

namespace SoftBodyDynamics.Tests.Editor
{
    /// <summary>What the authoring and baking tests share: a closed 1 m cube mesh and the codes of a list of issues.</summary>
    static class AuthoringTestData
    {
        /// <summary>The cube's 12 triangles over its 8 vertices, wound outwards ((b − a) × (c − a) points out).</summary>
        public static readonly int[] CubeTriangles =
        {
            0, 2, 1, 0, 3, 2, // −Z
            4, 5, 6, 4, 6, 7, // +Z
            0, 4, 7, 0, 7, 3, // −X
            1, 2, 6, 1, 6, 5, // +X
            0, 1, 5, 0, 5, 4, // −Y
            3, 7, 6, 3, 6, 2, // +Y
        };

        /// <summary>A new closed 1 m cube centred on the origin (<see cref="CubeTriangles"/>); the caller destroys it.</summary>
        public static Mesh CreateCubeMesh()
        {
            const float h = 0.5f;
            return new Mesh
            {
                vertices = new[]
                {
                    new Vector3(-h, -h, -h), new Vector3(h, -h, -h), new Vector3(h, h, -h), new Vector3(-h, h, -h),
                    new Vector3(-h, -h, h), new Vector3(h, -h, h), new Vector3(h, h, h), new Vector3(-h, h, h),
                },
                triangles = CubeTriangles,
            };
        }

        /// <summary>The codes of the issues of <paramref name="severity"/>, in order.</summary>
        public static List<IssueCode> Codes(List<ValidationIssue> issues, IssueSeverity severity)
        {
            var codes = new List<IssueCode>();
            foreach (ValidationIssue issue in issues)
                if (issue.Severity == severity)
                    codes.Add(issue.Code);
            return codes;
        }
    }
}
