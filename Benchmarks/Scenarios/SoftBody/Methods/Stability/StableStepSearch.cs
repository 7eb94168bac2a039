namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>What <see cref="StableStepSearch.Find"/> found.</summary>
    public readonly struct StableStepResult
    {
        /// <summary>The largest step (s) found bounded; <see cref="StableStepSearch.MaxStep"/> when <see cref="Capped"/>.</summary>
        public readonly double MaxStep;
        /// <summary>The largest step searched was bounded: the true limit is at least <see cref="MaxStep"/>.</summary>
        public readonly bool Capped;
        /// <summary>Runs at <see cref="MaxStep"/>/2 and /4 were made (see <see cref="StableStepSearch.Find"/>).</summary>
        public readonly bool BelowChecked;
        /// <summary>Runs at <see cref="MaxStep"/>/2 and /4 were bounded too (false when not <see cref="BelowChecked"/>).</summary>
        public readonly bool BoundedBelow;
        /// <summary>
        /// The largest step of the scan above the answer (<see cref="MaxStep"/> · 2ᵏ below the search's upper end) that was
        /// bounded (s); 0 when none was.
        /// </summary>
        public readonly double BoundedAbove;
        /// <summary>False when stability is not monotone in the step: a run below the answer failed, or one above it passed.</summary>
        public bool Monotone => BoundedBelow && BoundedAbove == 0;
        /// <summary>Why the smallest failing step searched failed (<see cref="UnboundedReason.None"/> when capped).</summary>
        public readonly UnboundedReason FailureAbove;
        /// <summary>Bounded runs made, the checks at /2 and /4 included.</summary>
        public readonly int Runs;
        /// <summary>Steps taken over all runs.</summary>
        public readonly long Steps;

        public StableStepResult(double maxStep, bool capped, bool belowChecked, bool boundedBelow, double boundedAbove, UnboundedReason failureAbove,
            int runs, long steps)
        {
            BelowChecked = belowChecked;
            MaxStep = maxStep;
            Capped = capped;
            BoundedBelow = boundedBelow;
            BoundedAbove = boundedAbove;
            FailureAbove = failureAbove;
            Runs = runs;
            Steps = steps;
        }
    }

    /// <summary>
    /// The largest stable step of a body: <see cref="LogBisection"/> of <see cref="BoundedRun"/> between
    /// <see cref="MinStep"/> (assumed bounded, not run: a run of it is 10⁶ steps) and <see cref="MaxStep"/> to a ratio of
    /// <see cref="Resolution"/>; then, to see whether stability is monotone in the step, runs at half and a quarter of the
    /// answer and at the answer times 2, 4, 8, … below the upper end (cheap: a run of a larger step has fewer steps). The runs
    /// at half and a quarter are the dear ones — an explicit method's are four and eight times its bisection's longest run —
    /// and are made only when asked for (the full run).
    /// </summary>
    public static class StableStepSearch
    {
        /// <summary>Lower end of the search (s).</summary>
        public const double MinStep = 1e-6;
        /// <summary>Upper end of the search (s): a body bounded there is reported as "≥ 1 s".</summary>
        public const double MaxStep = 1.0;
        /// <summary>Ratio of the smallest failing step to the answer at the end of the bisection.</summary>
        public const double Resolution = 1.05;

        public static StableStepResult Find(StabilityCube cube, IMethodBody body, bool checkBelow = true)
        {
            int runs = 0;
            long steps = 0;
            var failure = UnboundedReason.None;
            double failedAt = double.PositiveInfinity;
            bool Passes(double dt)
            {
                BoundedRunResult r = BoundedRun.Run(cube, body, (float)dt);
                runs++;
                steps += r.Steps;
                if (!r.Bounded && dt < failedAt)
                {
                    failedAt = dt;
                    failure = r.Reason;
                }
                return r.Bounded;
            }
            double best = LogBisection.Largest(Passes, MinStep, MaxStep, Resolution, out _);
            UnboundedReason failureAbove = failure;
            bool below = checkBelow && Passes(best / 2) & Passes(best / 4);
            double above = 0;
            for (double dt = 2 * best; dt < MaxStep; dt *= 2)
                if (Passes(dt))
                    above = dt;
            return new StableStepResult(best, best >= MaxStep, checkBelow, below, above, failureAbove, runs, steps);
        }
    }
}
