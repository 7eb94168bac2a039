using System.Collections.Generic;

namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>Every suite the headless runner and the Unity Performance tests run, in report order.</summary>
    public static class ScenarioCatalog
    {
        public static IReadOnlyList<IScenarioSuite> Suites { get; } = new IScenarioSuite[]
        {
            new RotationExtractionSuite(),
            new ShapeMatchingThroughputSuite(),
            new ShapeMatchingConvergenceSuite(),
            new ShapeMatchingFrameRateSuite(),
            new ShapeMatchingConservationSuite(),
            new MethodStudySuite(new CantileverScene()),
            new MethodStudySuite(new Csm3Scene()),
            new MethodStudySuite(new SquashScene()),
            new MethodStudySuite(new StretchScene()),
            new MethodStudyStabilitySuite(),
            new MethodStudyRankingSuite(),
            new SoftBodyMethodsThroughputSuite(),
            new FluidAccuracySuite(),
            new FluidPoiseuilleSuite(),
            new FluidStandingWaveSuite(),
            new FluidDropletSuite(),
            new FluidThroughputSuite(),
            new FluidCouplingSuite(),
            new EffectCostSuite(),
            new RendererEffectCostSuite(),
        };
    }
}
