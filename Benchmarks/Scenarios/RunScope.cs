namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>How much of each suite a run covers.</summary>
    public enum RunScope
    {
        /// <summary>A few points of each suite: a smoke test that every scenario runs (the test command's smoke run).</summary>
        Quick,
        /// <summary>
        /// The main job's default: every suite, each sweep cut to what keeps its figure's shape (at least three points per
        /// line) and its headline findings, in minutes.
        /// </summary>
        Standard,
        /// <summary>The whole study: every knob value and resolution of every sweep (tens of minutes).</summary>
        Full,
    }
}
