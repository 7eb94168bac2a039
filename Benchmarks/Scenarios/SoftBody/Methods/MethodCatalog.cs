using System.Collections.Generic;
using SoftBodyDynamics.Solvers;

namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>Every method of the study and the knob values it is swept over.</summary>
    public static class MethodCatalog
    {
        static readonly int[] s_SubstepKnobs = { 4, 16, 64 };
        static readonly int[] s_ExplicitKnobs = { 64, 128, 256 };
        static readonly int[] s_ImplicitKnobs = { 1, 4, 16 };

        /// <summary>The variants in report order.</summary>
        public static IReadOnlyList<MethodVariant> Variants { get; } = new List<MethodVariant>
        {
            new MethodVariant("SM rigid", "substeps", s_SubstepKnobs, new int[0],
                (s, k, h) => new ShapeMatchingMethodBody(s, ShapeMatchingMode.Rigid, k, h)),
            new MethodVariant("SM linear", "substeps", s_SubstepKnobs, new[] { 4 },
                (s, k, h) => new ShapeMatchingMethodBody(s, ShapeMatchingMode.Linear, k, h)),
            new MethodVariant("SM quadratic", "substeps", s_SubstepKnobs, new int[0],
                (s, k, h) => new ShapeMatchingMethodBody(s, ShapeMatchingMode.Quadratic, k, h)),
            new MethodVariant("MS symplectic Euler", "substeps", s_ExplicitKnobs, new int[0],
                (s, k, h) => new MassSpringMethodBody(s, MassSpringIntegrator.SymplecticEuler, k)),
            new MethodVariant("MS Verlet", "substeps", s_ExplicitKnobs, new int[0],
                (s, k, h) => new MassSpringMethodBody(s, MassSpringIntegrator.Verlet, k)),
            new MethodVariant("MS implicit Euler", "substeps", s_ImplicitKnobs, new int[0],
                (s, k, h) => new MassSpringMethodBody(s, MassSpringIntegrator.ImplicitEuler, k)),
            new MethodVariant("MS XPBD", "substeps", s_ImplicitKnobs, new[] { 4 },
                (s, k, h) => new MassSpringMethodBody(s, MassSpringIntegrator.Xpbd, k)),
            new MethodVariant("FEM co-rotational explicit", "substeps", s_ExplicitKnobs, new int[0],
                (s, k, h) => new FemMethodBody(s, FemMaterialModel.CoRotational, FemIntegrator.SymplecticEuler, k)),
            new MethodVariant("FEM co-rotational implicit", "substeps", s_ImplicitKnobs, new[] { 4 },
                (s, k, h) => new FemMethodBody(s, FemMaterialModel.CoRotational, FemIntegrator.ImplicitEuler, k)),
            new MethodVariant("FEM Neo-Hookean explicit", "substeps", s_ExplicitKnobs, new int[0],
                (s, k, h) => new FemMethodBody(s, FemMaterialModel.NeoHookean, FemIntegrator.SymplecticEuler, k)),
            new MethodVariant("FEM Neo-Hookean XPBD", "substeps", s_ImplicitKnobs, new int[0],
                (s, k, h) => new FemMethodBody(s, FemMaterialModel.NeoHookean, FemIntegrator.Xpbd, k)),
            new MethodVariant("Hybrid SM + MS XPBD", "substeps", s_SubstepKnobs, new int[0],
                (s, k, h) => new HybridMethodBody(s, k, h)),
        };

        /// <summary>The variant of the study whose finest setting serves as the reference where a scene has no independent one; null when none is available.</summary>
        public static MethodVariant ReferenceVariant => null;
    }
}
