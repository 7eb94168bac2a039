using System;
using SoftBodyDynamics.Solvers;

namespace SoftBodyDynamics.Authoring
{
    /// <summary>
    /// Builds a mass-spring or FEM body from a read mesh (bake time): <see cref="LatticeTetrahedralizer.Build"/> fills the
    /// closed mesh with tetrahedra and embeds the render vertices, then <see cref="MassSpringModelData.FromMesh"/>
    /// (springs calibrated to the material, <c>MassSpringCalibration</c>) or <see cref="FemModelData.Create"/> makes the
    /// model, and the explicit stable step is computed. A step that reports an error stops the build.
    /// </summary>
    public static class TetrahedralBodyBuilder
    {
        /// <summary>Builds <paramref name="method"/>'s model of <paramref name="mesh"/>.</summary>
        /// <param name="mesh">The render mesh at the baked scale.</param>
        /// <param name="method"><see cref="SoftBodyMethod.MassSpring"/> or <see cref="SoftBodyMethod.Fem"/>.</param>
        /// <param name="tetrahedralization">Resolution, node limit and weld settings.</param>
        /// <param name="material">The physical material (checked by the caller or by the model builders).</param>
        /// <param name="springs">Extra springs of the mass-spring network (ignored for FEM).</param>
        /// <param name="fem">The FEM element order, rest factor and constitutive model (for its stable step); ignored for mass-spring.</param>
        public static TetrahedralBodyBuild Build(SoftBodyMeshData mesh, SoftBodyMethod method, in TetrahedralizationSettings tetrahedralization,
            in ElasticMaterial material, in MassSpringBuildSettings springs, in FemBuildSettings fem)
        {
            if (mesh == null)
                throw new ArgumentNullException(nameof(mesh));
            if (method != SoftBodyMethod.MassSpring && method != SoftBodyMethod.Fem)
                throw new ArgumentOutOfRangeException(nameof(method), method, "Only the mass-spring and FEM methods use tetrahedra.");
            var build = new TetrahedralBodyBuild { Method = method };
            build.Tetrahedralization = LatticeTetrahedralizer.Build(mesh.Vertices, mesh.Triangles, tetrahedralization);
            build.Issues.AddRange(build.Tetrahedralization.Issues);
            if (!build.Tetrahedralization.Succeeded)
                return build;

            TetrahedralMesh volume = build.Tetrahedralization.Mesh;
            if (method == SoftBodyMethod.MassSpring)
            {
                build.MassSpring = MassSpringModelData.FromMesh(volume, material, springs, build.Issues, out _);
                if (build.MassSpring != null)
                    build.MaxStableStep = MassSpringStability.MaxStableStep(build.MassSpring.AsModel());
            }
            else
            {
                build.Fem = FemModelData.Create(volume, material, default, build.Issues, fem.Order);
                if (build.Fem != null)
                {
                    build.MaxStableStep = FemStability.MaxStableStep(build.Fem.AsModel(), fem.Model);
                    if (fem.RestFactor)
                    {
                        var parameters = FemParameters.Default;
                        parameters.DampingFrequency = fem.DampingFrequency;
                        float beta = FemSolver.DampingCoefficient(build.Fem.AsModel(), parameters.Sanitized());
                        if (!build.Fem.BuildRestFactor(fem.Substep, beta))
                            build.Issues.Add(ValidationIssue.Warning(FemIssueCode.RestFactorFailed, -1,
                                "The rest factor of the implicit step could not be built (its rest system is not positive definite in float64): "
                                + "the body uses the block-Jacobi preconditioner, with more iterations per substep."));
                    }
                }
            }
            return build;
        }
    }
}
