using System.Collections.Generic;
using SoftBodyDynamics.Solvers;

namespace SoftBodyDynamics.Authoring
{
    /// <summary>
    /// What baking a mass-spring or FEM body builds from a mesh: the tetrahedra and the render embedding, the method's
    /// model, the explicit stable step, and every issue found on the way (tetrahedralisation first, then the model's).
    /// </summary>
    public sealed class TetrahedralBodyBuild
    {
        /// <summary>Errors and warnings, in the order they were found.</summary>
        public readonly List<ValidationIssue> Issues = new List<ValidationIssue>();
        /// <summary>The method the model was built for (<see cref="SoftBodyMethod.MassSpring"/> or <see cref="SoftBodyMethod.Fem"/>).</summary>
        public SoftBodyMethod Method;
        /// <summary>The volume mesh and the render embedding; null when the settings were invalid.</summary>
        public TetrahedralizationResult Tetrahedralization;
        /// <summary>The mass-spring model (springs calibrated to the material); null unless built for that method without error.</summary>
        public MassSpringModelData MassSpring;
        /// <summary>The finite-element model; null unless built for that method without error.</summary>
        public FemModelData Fem;
        /// <summary>
        /// Largest step (s) an explicit integrator stays stable at for this model (h &lt; 2/ω_max); +∞ when no model was
        /// built. Computed by power iteration at bake time (<c>MassSpringStability</c>, <c>FemStability</c>).
        /// </summary>
        public double MaxStableStep = double.PositiveInfinity;

        /// <summary>True when the model for <see cref="Method"/> was built and no issue is an error.</summary>
        public bool Succeeded => Tetrahedralization != null && Tetrahedralization.Succeeded && !ValidationIssue.AnyError(Issues)
                                 && (Method == SoftBodyMethod.MassSpring ? MassSpring != null : Fem != null);

        /// <summary>Nodes (particles) of the volume mesh; 0 when none was built.</summary>
        public int NodeCount => Tetrahedralization?.Mesh?.NodeCount ?? 0;
        /// <summary>Tetrahedra of the volume mesh; 0 when none was built.</summary>
        public int TetrahedronCount => Tetrahedralization?.Mesh?.TetrahedronCount ?? 0;
        /// <summary>Springs of the mass-spring model; 0 without one.</summary>
        public int SpringCount => MassSpring?.SpringCount ?? 0;
    }
}
