using System.Collections.Generic;
using SoftBodyDynamics.Solvers;

namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>Every method of the study and the knob values it is swept over.</summary>
    public static class MethodCatalog
    {
        static readonly int[] s_SubstepKnobs = { 4, 16, 64 };

        /// <summary>The variants in report order.</summary>
        public static IReadOnlyList<MethodVariant> Variants { get; } = new List<MethodVariant>
        {
            new MethodVariant("SM rigid", "substeps", s_SubstepKnobs, new int[0],
                (s, k, h) => new ShapeMatchingMethodBody(s, ShapeMatchingMode.Rigid, k, h)),
            new MethodVariant("SM linear", "substeps", s_SubstepKnobs, new[] { 4 },
                (s, k, h) => new ShapeMatchingMethodBody(s, ShapeMatchingMode.Linear, k, h)),
            new MethodVariant("SM quadratic", "substeps", s_SubstepKnobs, new int[0],
                (s, k, h) => new ShapeMatchingMethodBody(s, ShapeMatchingMode.Quadratic, k, h)),
        };

        /// <summary>The variant of the study whose finest setting serves as the reference where a scene has no independent one; null when none is available.</summary>
        public static MethodVariant ReferenceVariant => null;
    }
}
