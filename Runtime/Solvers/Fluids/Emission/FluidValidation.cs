using System;
using System.Collections.Generic;
using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>Bake-time checks of a fluid, its taps and drains: each problem is a specific, actionable <see cref="ValidationIssue"/>.</summary>
    public static class FluidValidation
    {
        /// <summary>Speed of sound above which the substeps are absurd for real time (m/s; water's real value).</summary>
        public const float MaxSpeedOfSound = 1500f;

        /// <summary>Checks a fluid's parameters and budget; adds issues to <paramref name="issues"/>. Returns false on an error.</summary>
        public static bool Validate(in FluidParameters p, int budget, List<ValidationIssue> issues)
        {
            int start = issues.Count;
            if (!(p.ParticleSpacing > 0f) || !math.isfinite(p.ParticleSpacing))
                issues.Add(ValidationIssue.Error(FluidIssueCode.SpacingInvalid, -1, $"Particle spacing must be a positive length in metres (is {p.ParticleSpacing})."));
            if (!(p.KernelRadiusRatio >= 1.5f && p.KernelRadiusRatio <= 4f))
                issues.Add(ValidationIssue.Error(FluidIssueCode.KernelRatioInvalid, -1, $"Kernel radius ratio h/Δx must be between 1.5 and 4 (is {p.KernelRadiusRatio}); 2 gives about 30 neighbours."));
            if (!(p.RestDensity > 0f) || !math.isfinite(p.RestDensity))
                issues.Add(ValidationIssue.Error(FluidIssueCode.DensityInvalid, -1, $"Rest density must be positive, in kg/m³ (water 1000; is {p.RestDensity})."));
            if (!(p.SpeedOfSound > 0f) || !(p.SpeedOfSound <= MaxSpeedOfSound))
                issues.Add(ValidationIssue.Error(FluidIssueCode.SpeedOfSoundInvalid, -1, $"Speed of sound must be in (0, {MaxSpeedOfSound}] m/s (is {p.SpeedOfSound}); 10·√(v² + gH) for the fastest flow v and depth H keeps the density error near 1 %."));
            float3 extent = p.DomainMax - p.DomainMin;
            float h = p.ParticleSpacing * p.KernelRadiusRatio;
            if (!math.all(math.isfinite(extent)) || math.any(extent < h))
                issues.Add(ValidationIssue.Error(FluidIssueCode.DomainInvalid, -1, $"The domain box must be finite and at least one kernel radius ({h} m) along every axis (size {extent})."));
            else if (h > 0f && math.isfinite(h))
            {
                double cells = Math.Ceiling(extent.x / (h / FluidGrid.SearchRange)) * Math.Ceiling(extent.y / (h / FluidGrid.SearchRange)) * Math.Ceiling(extent.z / (h / FluidGrid.SearchRange));
                if (cells > FluidGrid.MaxCells)
                    issues.Add(ValidationIssue.Warning(FluidIssueCode.GridTooLarge, -1, $"The domain holds {cells:0} grid cells, more than {FluidGrid.MaxCells}: cells get coarser and the neighbour search slower. Shrink the domain or increase the spacing."));
            }
            if (budget <= 0)
                issues.Add(ValidationIssue.Error(FluidIssueCode.BudgetInvalid, -1, $"The particle budget must be positive (is {budget})."));
            if (!NonNegative(p.Viscosity) || !NonNegative(p.CohesionWeight) || !NonNegative(p.SeparationWeight) || !NonNegative(p.AlignmentRate) || !NonNegative(p.XsphRate) || !NonNegative(p.SurfaceTension) || !NonNegative(p.ArtificialViscosity))
                issues.Add(ValidationIssue.Error(FluidIssueCode.CoefficientInvalid, -1, "Viscosity, artificial viscosity, cohesion, separation, alignment, XSPH rate and surface tension must be finite and not negative."));
            if (!Share(p.WallFriction) || !Share(p.WallNoSlip) || !Share(p.DomainFriction.x) || !Share(p.DomainFriction.y) || !Share(p.DomainFriction.z)
                || !Share(p.DomainNoSlip.x) || !Share(p.DomainNoSlip.y) || !Share(p.DomainNoSlip.z))
                issues.Add(ValidationIssue.Warning(FluidIssueCode.WallShareOutOfRange, -1,
                    $"Wall friction μ and no-slip shares must be between 0 and 1 (colliders μ {p.WallFriction}, no-slip {p.WallNoSlip}; domain faces μ {p.DomainFriction}, no-slip {p.DomainNoSlip}): the step uses the nearest of 0 and 1, NaN as 0."));
            if (!ValidationIssue.AnyError(issues, start))
            {
                float shortest = FluidParameters.MinPeriodicExtentRatio * h;
                if ((p.Periodic.x && extent.x < shortest) || (p.Periodic.y && extent.y < shortest) || (p.Periodic.z && extent.z < shortest))
                    issues.Add(ValidationIssue.Warning(FluidIssueCode.PeriodicAxisTooShort, -1, $"A periodic axis is shorter than three kernel radii ({shortest} m; size {extent}), so it is not periodic: lengthen the domain or lower the spacing."));
                var c = new FluidConstants(p);
                int2 substeps = FluidSolver.Substeps(c, 0f, 0f, 1f / 60f);
                int needed = FluidSolver.ViscosityIterationsNeeded(c, 1f / 60f / substeps.y);
                if (needed > FluidParameters.MaxViscosityIterations && c.Parameters.Viscosity > 0f && c.Parameters.ViscosityIterations > 0)
                    issues.Add(ValidationIssue.Warning(FluidIssueCode.ViscosityUnresolved, -1, $"At this viscosity, spacing and substep the implicit viscosity needs {needed} Jacobi iterations to reach 1 % of its solution, more than the {FluidParameters.MaxViscosityIterations} a substep runs: a steady flow will run faster than the fluid's viscosity allows. Raise the spacing or the speed of sound (shorter substeps), or lower the viscosity."));
                if (p.MinSubsteps > p.MaxSubsteps)
                    issues.Add(ValidationIssue.Warning(FluidIssueCode.SubstepCapTooLow, -1, $"The fewest substeps ({p.MinSubsteps}) are above the cap ({p.MaxSubsteps}): the step takes {p.MaxSubsteps}. Raise the cap or lower the minimum."));
                else if (substeps.x > substeps.y)
                    issues.Add(ValidationIssue.Warning(FluidIssueCode.SubstepCapTooLow, -1, $"At rest the CFL limit already asks for {substeps.x} substeps per 1/60 s frame, above the cap of {substeps.y}: lower the speed of sound or raise the substep cap."));
                else if (c.Parameters.Solver == FluidSolverKind.PositionBased)
                {
                    // The depth rule for water filling the domain's height (the deepest the fluid can be).
                    float3 g = c.Parameters.Gravity;
                    float depth = math.lengthsq(g) > 0f ? math.abs(math.dot(c.Parameters.DomainMax - c.Parameters.DomainMin, math.normalize(g))) : 0f;
                    int2 deep = FluidSolver.Substeps(c, 0f, depth, 1f / 60f);
                    if (deep.x > deep.y)
                        issues.Add(ValidationIssue.Warning(FluidIssueCode.SubstepCapTooLow, -1, $"Fluid {depth:0.##} m deep (the domain's height) needs {deep.x} substeps per 1/60 s frame to keep its density error near 1 % with {c.Parameters.PressureIterations} iterations, above the cap of {deep.y}: deeper fluid will run in slow motion. Raise the iterations or the substep cap, or lower the domain."));
                }
            }
            return !ValidationIssue.AnyError(issues, start);
        }

        static bool Share(float value) => value >= 0f && value <= 1f;

        /// <summary>Checks a tap against its fluid (spacing and budget); adds issues. Returns false on an error.</summary>
        public static bool ValidateTap(in FluidTapSettings s, ReadOnlySpan<FluidTapBurst> bursts, float spacing, int budget, List<ValidationIssue> issues)
        {
            int start = issues.Count;
            if ((uint)s.Shape > (uint)FluidTapShape.Box)
                issues.Add(ValidationIssue.Error(FluidEmissionIssueCode.TapShapeInvalid, -1, "The tap shape must be Point, Disc, Sphere or Box."));
            if (!NonNegative(s.Radius) || !NonNegative(s.HalfExtents.x) || !NonNegative(s.HalfExtents.y) || !NonNegative(s.HalfExtents.z))
                issues.Add(ValidationIssue.Error(FluidEmissionIssueCode.TapSizeInvalid, -1, "The tap radius and half extents must be finite and not negative (m)."));
            float4 q = s.Rotation.value;
            if (!math.all(math.isfinite(q)) || math.dot(q, q) < 1e-12f)
                issues.Add(ValidationIssue.Error(FluidEmissionIssueCode.TapDirectionInvalid, -1, "The tap rotation is not a valid rotation: the flow has no direction."));
            if (!(s.ConeAngle >= 0f && s.ConeAngle < 180f))
                issues.Add(ValidationIssue.Error(FluidEmissionIssueCode.TapConeInvalid, -1, $"The cone angle must be in [0°, 180°) (is {s.ConeAngle}°)."));
            if (!NonNegative(s.Speed) || !NonNegative(s.SpeedRandom) || s.SpeedRandom > s.Speed)
                issues.Add(ValidationIssue.Error(FluidEmissionIssueCode.TapSpeedInvalid, -1, $"Speed must be ≥ 0 m/s and its random range between 0 and the speed (speed {s.Speed}, range {s.SpeedRandom})."));
            if (!NonNegative(s.Rate) || !NonNegative(s.VolumeFlow))
                issues.Add(ValidationIssue.Error(FluidEmissionIssueCode.TapRateInvalid, -1, "Rate (particles/s) and volume flow (L/s) must be finite and not negative."));
            if (!NonNegative(s.PulsePeriod) || !(s.PulseDutyCycle > 0f && s.PulseDutyCycle <= 1f))
                issues.Add(ValidationIssue.Error(FluidEmissionIssueCode.TapPulseInvalid, -1, $"Pulse period must be ≥ 0 s and the duty cycle in (0, 1] (is {s.PulseDutyCycle})."));
            if (!NonNegative(s.Duration) || !NonNegative(s.StartDelay) || !NonNegative(s.Prewarm))
                issues.Add(ValidationIssue.Error(FluidEmissionIssueCode.TapTimingInvalid, -1, "Duration, start delay and prewarm must be finite and not negative (s)."));
            for (int b = 0; b < bursts.Length; b++)
            {
                FluidTapBurst burst = bursts[b];
                if (!(burst.Time >= 0f) || burst.Count < 0 || burst.Cycles < 1 || (burst.Cycles > 1 && !(burst.Interval > 0f)))
                    issues.Add(ValidationIssue.Error(FluidEmissionIssueCode.TapBurstInvalid, b, $"Burst {b}: time ≥ 0 s, count ≥ 0, cycles ≥ 1 and a positive interval when it repeats (time {burst.Time}, count {burst.Count}, cycles {burst.Cycles}, interval {burst.Interval})."));
            }
            if (!NonNegative(s.Lifetime) || !NonNegative(s.LifetimeRandom) || s.LifetimeRandom > s.Lifetime)
                issues.Add(ValidationIssue.Error(FluidEmissionIssueCode.TapLifetimeInvalid, -1, $"Lifetime must be ≥ 0 s (0 = forever) and its random range between 0 and the lifetime (lifetime {s.Lifetime}, range {s.LifetimeRandom})."));
            if (!ValidationIssue.AnyError(issues, start))
            {
                long burstTotal = 0;
                for (int b = 0; b < bursts.Length; b++)
                    burstTotal += bursts[b].Count;
                if (s.ParticlesPerSecond(spacing) <= 0f && burstTotal == 0)
                    issues.Add(ValidationIssue.Warning(FluidEmissionIssueCode.TapSilent, -1, "The tap emits nothing: its rate is 0 and it has no bursts."));
                double alive = FluidTapSchedule.SteadyStateAlive(s, bursts, spacing);
                if (budget > 0 && alive > budget)
                    issues.Add(ValidationIssue.Error(FluidEmissionIssueCode.TapOverBudget, -1, double.IsInfinity(alive)
                        ? $"Particles live forever and the tap never stops: the fluid's budget of {budget} fills up and the tap stalls. Give the particles a lifetime, add a drain and set Max Alive, or give the tap a duration."
                        : $"The tap sustains about {alive:0} alive particles (rate × lifetime), more than the fluid's budget of {budget}. Lower the rate or the lifetime, or raise the budget."));
            }
            return !ValidationIssue.AnyError(issues, start);
        }

        /// <summary>Checks a drain's shape; adds issues. Returns false on an error.</summary>
        public static bool ValidateDrain(in FluidDrain drain, int index, List<ValidationIssue> issues)
        {
            ColliderShape c = drain.Shape;
            bool ok = math.all(math.isfinite(c.Center)) && c.Type switch
            {
                ColliderShapeType.Sphere => c.Radius > 0f && math.isfinite(c.Radius),
                ColliderShapeType.Capsule => c.Radius > 0f && math.isfinite(c.Radius) && math.all(math.isfinite(c.Axis)),
                ColliderShapeType.Box => math.all(c.HalfExtents > 0f) && math.all(math.isfinite(c.HalfExtents)),
                ColliderShapeType.Plane => math.all(math.isfinite(c.Axis)) && math.lengthsq(c.Axis) > 0f,
                _ => false,
            };
            if (!ok)
                issues.Add(ValidationIssue.Error(FluidEmissionIssueCode.DrainInvalid, index, $"Drain {index}: its size must be positive and finite."));
            return ok;
        }

        static bool NonNegative(float v) => v >= 0f && math.isfinite(v);
    }
}
