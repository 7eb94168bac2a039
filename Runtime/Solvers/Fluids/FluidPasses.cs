using System;
using Unity.Mathematics;

namespace SoftBodyDynamics.Solvers
{
    /// <summary>Counters a pass adds up over its range (all order-independent: sums of integers and a maximum).</summary>
    public struct FluidPassCounters
    {
        public int Killed, Expired, Invalid, SpeedClamped, OverCompressed, NeighbourOverflow, Contacts;
        public float MaxDensityRatio;

        /// <summary>Adds another range's counters (the order does not change the result).</summary>
        public void Add(in FluidPassCounters o)
        {
            Killed += o.Killed;
            Expired += o.Expired;
            Invalid += o.Invalid;
            SpeedClamped += o.SpeedClamped;
            OverCompressed += o.OverCompressed;
            NeighbourOverflow += o.NeighbourOverflow;
            Contacts += o.Contacts;
            MaxDensityRatio = math.max(MaxDensityRatio, o.MaxDensityRatio);
        }
    }

    /// <summary>
    /// The passes of a fluid substep, each over a range [start, end) of particle slots so a job can run it in
    /// batches; a pass reads other particles only from arrays no pass of the same kind writes, so every batch split
    /// gives the same bits. <see cref="FluidSolver"/> calls them in order for the single-threaded reference step.
    /// </summary>
    public static class FluidPasses
    {
        /// <summary>
        /// Grid key of each slot in [start, end); a slot whose particle must go gets <see cref="FluidGrid.DeadKey"/>:
        /// marked by a drain (negative lifetime), past its lifetime, or with a non-finite position or velocity.
        /// </summary>
        public static void Keys(in FluidConstants c, FluidParticles p, FluidScratch s, int start, int end, ref FluidPassCounters counters)
        {
            int dead = c.Grid.DeadKey;
            for (int i = start; i < end; i++)
            {
                float life = p.Lifetimes[i];
                float3 x = p.Positions[i];
                int key;
                if (life < 0f || math.isnan(life)) { key = dead; counters.Killed++; }
                else if (life > 0f && p.Ages[i] >= life) { key = dead; counters.Expired++; }
                else if (!math.all(math.isfinite(x)) || !math.all(math.isfinite(p.Velocities[i]))) { key = dead; counters.Invalid++; }
                else key = c.Grid.Key(x);
                s.Keys[i] = key;
            }
        }

        /// <summary>
        /// Stable counting sort of slots [0, total) by key (Green 2008; Hoetzlein 2014): histogram with each slot's
        /// rank in its cell, exclusive prefix sum into <see cref="FluidScratch.CellStart"/>, then
        /// Order[CellStart[key] + rank] = slot. Dead slots land after every live one. Returns the live count.
        /// Sequential (the histogram's ranks fix the order); the permutation is applied by <see cref="Permute{T}"/>.
        /// </summary>
        public static int Sort(in FluidGrid grid, FluidScratch s, int total)
        {
            int cells = grid.CellCount;
            Span<int> start = s.CellStart.Slice(0, cells + 2);
            start.Clear();
            for (int i = 0; i < total; i++)
            {
                int k = s.Keys[i];
                s.Ints[i] = start[k + 1]++;
            }
            for (int k = 1; k < cells + 2; k++)
                start[k] += start[k - 1];
            for (int i = 0; i < total; i++)
                s.Order[start[s.Keys[i]] + s.Ints[i]] = i;
            return start[cells];
        }

        /// <summary>temp[k] = data[Order[k]] for k in [start, end): the gather half of applying the sort.</summary>
        public static void Gather<T>(ReadOnlySpan<T> data, Span<T> temp, ReadOnlySpan<int> order, int start, int end) where T : unmanaged
        {
            for (int k = start; k < end; k++)
                temp[k] = data[order[k]];
        }

        /// <summary>Applies the sort's permutation to the first <paramref name="count"/> slots of <paramref name="data"/> through <paramref name="temp"/>.</summary>
        public static void Permute<T>(Span<T> data, Span<T> temp, ReadOnlySpan<int> order, int count) where T : unmanaged
        {
            Gather<T>(data, temp, order, 0, count);
            temp.Slice(0, count).CopyTo(data);
        }

        /// <summary>
        /// Density ρᵢ = Σⱼ m·W_poly6(|xᵢ − xⱼ|) (Müller 2003, eq. 3) and the neighbour list of each slot; the walls count as the
        /// neighbours' mirror images (weakly compressible, <see cref="FluidGhostWalls"/>) or as static boundary matter
        /// (position-based, <see cref="FluidBoundary.Sample"/>). Weakly compressible: the Tait pressure (Becker &amp; Teschner 2007,
        /// eq. 6) p = B·((ρ/ρ₀)^γ − 1) of the density clamped to at least ρ₀ (no negative pressure at the free
        /// surface, where the kernel lacks neighbours; SPlisHSPlasH clamps the same way), stored as κᵢ·p/ρ² with κᵢ the
        /// particle's gradient renormalization (<see cref="FluidConstants.GradientRenormalization"/>).
        /// </summary>
        public static void Density(in FluidConstants c, ReadOnlySpan<ColliderShape> colliders, FluidParticles p, FluidScratch s,
            int start, int end, ref FluidPassCounters counters)
        {
            if (c.IsPeriodic)
                Density(c, colliders, p, s, start, end, ref counters, new NearestImageOffset(c));
            else
                Density(c, colliders, p, s, start, end, ref counters, default(DirectOffset));
        }

        static void Density<TOffset>(in FluidConstants c, ReadOnlySpan<ColliderShape> colliders, FluidParticles p, FluidScratch s,
            int start, int end, ref FluidPassCounters counters, TOffset offset) where TOffset : struct, IPairOffset
        {
            SphKernels k = c.Kernels;
            float rho0 = c.Parameters.RestDensity, h2 = k.H2;
            bool tait = c.Parameters.Solver == FluidSolverKind.WeaklyCompressible;
            bool bulk = tait && c.BulkPressureScale > 0f;
            const int cap = FluidScratch.MaxNeighbours;
            ReadOnlySpan<float3> x = p.Positions, velocities = p.Velocities;
            ReadOnlySpan<int> cellStart = s.CellStart;
            Span<int> neighbours = s.Neighbours;
            for (int i = start; i < end; i++)
            {
                float3 xi = x[i];
                NeighbourRows rows = NeighbourRows.Find(c.Grid, cellStart, xi);
                int listStart = i * cap, found = 0;
                // Σ (h² − r²)³ over neighbours; the poly6 coefficient is applied once. With bulk viscosity also
                // Σ (vᵢ − vⱼ)·xᵢⱼ·(h² − r²)², the poly6-gradient divergence up to its factor (FluidConstants.BulkPressureScale).
                // Weakly compressible also Σ (h − r)²·r, the spiky gradient's trace up to its factor (GradientRenormalization).
                float sum = 0f, divergence = 0f, spiky = 0f;
                float3 vi = bulk ? velocities[i] : float3.zero;
                for (int r = 0; r < rows.Count; r++)
                {
                    int rowEnd = rows.End(r);
                    for (int j = rows.Begin(r); j < rowEnd; j++)
                    {
                        float3 d = offset.Of(xi, x[j]);
                        float q = h2 - (d.x * d.x + d.y * d.y + d.z * d.z);
                        if (!(q > 0f))
                            continue;
                        sum += q * q * q;
                        if (j == i)
                            continue;
                        if (tait)
                        {
                            float distance = math.sqrt(h2 - q);
                            float hr = k.H - distance;
                            spiky += hr * hr * distance;
                        }
                        if (bulk)
                            divergence += math.dot(vi - velocities[j], d) * (q * q);
                        if (found < cap)
                            neighbours[listStart + found++] = j;
                        else
                            counters.NeighbourOverflow++;
                    }
                }
                s.NeighbourCounts[i] = found;
                if (tait)
                {
                    var walls = FluidGhostWalls.Near(c, colliders, xi);
                    if (walls.Count > 0)
                        GhostDensity(c, walls, colliders, x, velocities, neighbours.Slice(listStart, found), xi, vi, bulk, ref sum, ref spiky, ref divergence, offset);
                }
                float rho = StoreDensity(c, colliders, s, i, xi, sum, ref counters);
                if (tait)
                {
                    float rc = math.max(rho, rho0);
                    float pressure = c.TaitPressure(rho);
                    if (bulk)
                        // Bulk-viscous p_b = −ρ₀ζ·∇·vᵢ; the total stays ≥ 0 like the Tait pressure, so expansion never pulls.
                        pressure = math.max(pressure - c.BulkPressureScale * divergence / rho, 0f);
                    s.Pressures[i] = c.GradientRenormalization(spiky, rho) * pressure / (rc * rc);
                }
            }
        }

        /// <summary>
        /// Density from the neighbour lists of the last <see cref="Density"/> pass, for positions that moved a little
        /// since (the position-based iterations keep their lists, Macklin &amp; Müller 2013, Algorithm 1). No pressure.
        /// </summary>
        public static void DensityFromNeighbours(in FluidConstants c, ReadOnlySpan<ColliderShape> colliders, FluidParticles p,
            FluidScratch s, int start, int end, ref FluidPassCounters counters)
        {
            float h2 = c.Kernels.H2;
            const int cap = FluidScratch.MaxNeighbours;
            ReadOnlySpan<float3> x = p.Positions;
            ReadOnlySpan<int> neighbours = s.Neighbours;
            for (int i = start; i < end; i++)
            {
                float3 xi = x[i];
                // The particle itself contributes W(0) = coefficient·h⁶.
                float sum = h2 * h2 * h2;
                ReadOnlySpan<int> list = neighbours.Slice(i * cap, s.NeighbourCounts[i]);
                for (int n = 0; n < list.Length; n++)
                {
                    float3 d = c.Offset(xi, x[list[n]]);
                    float q = h2 - (d.x * d.x + d.y * d.y + d.z * d.z);
                    if (q > 0f)
                        sum += q * q * q;
                }
                StoreDensity(c, colliders, s, i, xi, sum, ref counters);
            }
        }

        /// <summary>
        /// Weakly compressible: the walls' ghosts' share of the Density pass's sums for a particle near <paramref name="walls"/>:
        /// for every set of walls, the images of the particle itself and of each neighbour in <paramref name="list"/> add
        /// (h² − r²)³ and (h − r)²·r, and with <paramref name="bulk"/> (vᵢ − v_g)·xᵢ_g·(h² − r²)² with the image's mirrored
        /// velocity (free slip).
        /// </summary>
        static void GhostDensity<TOffset>(in FluidConstants c, in FluidGhostWalls walls, ReadOnlySpan<ColliderShape> colliders, ReadOnlySpan<float3> x, ReadOnlySpan<float3> velocities,
            ReadOnlySpan<int> list, float3 xi, float3 vi, bool bulk, ref float sum, ref float spiky, ref float divergence, TOffset offset)
            where TOffset : struct, IPairOffset
        {
            float h = c.Kernels.H, h2 = c.Kernels.H2;
            int subsets = walls.Subsets;
            for (int subset = 1; subset <= subsets; subset++)
                for (int m = -1; m < list.Length; m++)
                {
                    float3 y = m < 0 ? float3.zero : -offset.Of(xi, x[list[m]]);
                    float3 v = m < 0 ? vi : bulk ? velocities[list[m]] : float3.zero;
                    if (!walls.Mirror(subset, xi, colliders, ref y, ref v))
                        continue;
                    float q = h2 - (y.x * y.x + y.y * y.y + y.z * y.z);
                    if (!(q > 0f))
                        continue;
                    sum += q * q * q;
                    float distance = math.sqrt(h2 - q);
                    float hr = h - distance;
                    spiky += hr * hr * distance;
                    if (bulk)
                        divergence -= math.dot(vi - v, y) * (q * q);
                }
        }

        /// <summary>
        /// ρᵢ = m·(poly6 coefficient)·Σ(h² − r²)³, the weakly compressible walls' ghosts included in the sum, plus for
        /// position-based fluids ρ₀·(the walls' share, <see cref="FluidBoundary.Sample"/>), stored, with the density ratio counted
        /// against the bound; returns ρᵢ. The end of <see cref="Density"/> and <see cref="DensityFromNeighbours"/>.
        /// </summary>
        static float StoreDensity(in FluidConstants c, ReadOnlySpan<ColliderShape> colliders, FluidScratch s, int i, float3 xi,
            float kernelSum, ref FluidPassCounters counters)
        {
            float rho0 = c.Parameters.RestDensity;
            float wall = 0f;
            if (c.Parameters.Solver == FluidSolverKind.PositionBased)
                FluidBoundary.Sample(c, colliders, xi, out wall, out _);
            float rho = c.Mass * c.Kernels.Poly6Coefficient * kernelSum + rho0 * wall;
            s.Densities[i] = rho;
            float ratio = rho / rho0;
            counters.MaxDensityRatio = math.max(counters.MaxDensityRatio, ratio);
            if (ratio > c.Parameters.MaxDensityRatio)
                counters.OverCompressed++;
            return rho;
        }

        /// <summary>Akinci et al. 2013 surface normals nᵢ = h·Σⱼ (m/ρⱼ)·∇W(xᵢ − xⱼ) (eq. 4) into <see cref="FluidScratch.VectorsB"/>.</summary>
        public static void SurfaceNormals(in FluidConstants c, FluidParticles p, FluidScratch s, int start, int end)
        {
            SphKernels k = c.Kernels;
            float m = c.Mass;
            const int cap = FluidScratch.MaxNeighbours;
            for (int i = start; i < end; i++)
            {
                float3 xi = p.Positions[i];
                float3 n = float3.zero;
                int count = s.NeighbourCounts[i];
                for (int a = 0; a < count; a++)
                {
                    int j = s.Neighbours[i * cap + a];
                    float3 rij = c.Offset(xi, p.Positions[j]);
                    n += (m / s.Densities[j]) * k.SpikyGradientScale(math.length(rij)) * rij;
                }
                s.VectorsB[i] = k.H * n;
            }
        }

        /// <summary>
        /// Accelerations and the velocity update vᵢ += h·aᵢ. Weakly compressible adds gravity, the symmetric pressure
        /// term −Σⱼ m·(κᵢpᵢ/ρᵢ² + κⱼpⱼ/ρⱼ²)·∇W_spiky (Müller 2003, eq. 10 in its momentum-conserving form; Monaghan 1992;
        /// κ the per-particle renormalization stored with the pressure)
        /// with Monaghan's artificial viscosity Πᵢⱼ (Becker &amp; Teschner 2007, eq. 11), the walls' ghosts taking part in the
        /// sum as neighbours (<see cref="FluidGhostWalls"/>). Both solvers add the cohesion of
        /// <see cref="FluidParameters.Cohesion"/>. Writes vᵢ + h·aᵢ to <paramref name="destination"/> (neighbours'
        /// velocities are read). Coincident particles (r = 0) are pushed apart along a direction fixed by their ids.
        /// </summary>
        public static void Forces(in FluidConstants c, ReadOnlySpan<ColliderShape> colliders, FluidParticles p, FluidScratch s,
            Span<float3> destination, int start, int end, float h, bool pressureAndGravity)
        {
            if (c.IsPeriodic)
                Forces(c, colliders, p, s, destination, start, end, h, pressureAndGravity, new NearestImageOffset(c));
            else
                Forces(c, colliders, p, s, destination, start, end, h, pressureAndGravity, default(DirectOffset));
        }

        static void Forces<TOffset>(in FluidConstants c, ReadOnlySpan<ColliderShape> colliders, FluidParticles p, FluidScratch s,
            Span<float3> destination, int start, int end, float h, bool pressureAndGravity, TOffset offset) where TOffset : struct, IPairOffset
        {
            FluidParameters prm = c.Parameters;
            bool flocking = prm.Cohesion == FluidCohesionModel.Flocking && (prm.CohesionWeight > 0f || prm.SeparationWeight > 0f);
            bool akinci = prm.Cohesion == FluidCohesionModel.Akinci && prm.SurfaceTension > 0f;
            for (int i = start; i < end; i++)
            {
                float3 a = float3.zero;
                if (pressureAndGravity)
                    a += PressureAcceleration(c, colliders, p, s, i, offset);
                if (flocking)
                    AddFlocking(c, p, s, i, ref a, offset);
                if (akinci)
                    a -= prm.SurfaceTension * AkinciSum(c, p, s, i, offset);
                destination[i] = p.Velocities[i] + h * a;
            }
        }

        /// <summary>
        /// Weakly compressible part of <see cref="Forces"/> for slot <paramref name="i"/>: gravity and the symmetric pressure term
        /// with artificial viscosity over the neighbours and the walls' ghosts.
        /// </summary>
        static float3 PressureAcceleration<TOffset>(in FluidConstants c, ReadOnlySpan<ColliderShape> colliders, FluidParticles p, FluidScratch s, int i,
            TOffset offset) where TOffset : struct, IPairOffset
        {
            SphKernels k = c.Kernels;
            FluidParameters prm = c.Parameters;
            float alphaCh = 2f * c.EffectiveArtificialViscosity * prm.SpeedOfSound * k.H;
            float eta2 = 0.01f * k.H2;
            float minDistance = 1e-6f * k.H;
            ReadOnlySpan<float3> x = p.Positions, velocities = p.Velocities;
            ReadOnlySpan<float> pressures = s.Pressures, densities = s.Densities;
            float3 xi = x[i];
            float pi = pressures[i];
            float rhoi = densities[i];
            float3 vi = velocities[i];
            float3 sum = float3.zero;
            ReadOnlySpan<int> list = s.Neighbours.Slice(i * FluidScratch.MaxNeighbours, s.NeighbourCounts[i]);
            for (int n = 0; n < list.Length; n++)
            {
                int j = list[n];
                float3 rij = offset.Of(xi, x[j]);
                float r2 = math.dot(rij, rij);
                float r = math.sqrt(r2);
                float scale = pi + pressures[j];
                // Πᵢⱼ = −2αhc₀/(ρᵢ + ρⱼ) · vᵢⱼ·xᵢⱼ / (|xᵢⱼ|² + 0.01h²) for approaching pairs only.
                float approach = math.min(math.dot(vi - velocities[j], rij), 0f);
                scale -= alphaCh * approach / ((rhoi + densities[j]) * (r2 + eta2));
                if (r > minDistance)
                {
                    // Spiky ∇W = −45/(πh⁶)(h − r)²·r̂; the coefficient and −m are applied after the loop.
                    float hr = math.max(k.H - r, 0f);
                    sum += (scale * hr * hr / r) * rij;
                }
                else
                    // ∇W at r → 0⁺ has magnitude 45/(πh⁶)·h²; the direction comes from the pair's ids (antisymmetric).
                    sum += scale * k.H2 * CoincidentDirection(p.Ids[i], p.Ids[j]);
            }
            var walls = FluidGhostWalls.Near(c, colliders, xi);
            if (walls.Count > 0)
                sum += GhostPressure(c, walls, colliders, p, s, list, xi, vi, pi, rhoi, alphaCh, 0, 0, offset);
            sum *= -c.Mass * k.SpikyGradientCoefficient * c.GradientCorrection;
            return prm.Gravity + sum;
        }

        /// <summary>
        /// Weakly compressible: the force (N) each collider from index <paramref name="firstMoving"/> on takes from the fluid
        /// through its walls' ghosts, summed over slots [start, end) in slot order into <paramref name="forces"/> (one per such
        /// collider, added to), and its torque (N·m) about the collider's centre, the force acting at the particle, into
        /// <paramref name="torques"/>: for particle i, −mᵢ times the ghosts' share of its pressure acceleration
        /// (<see cref="PressureAcceleration"/>, artificial viscosity included), a ghost through several moving walls split
        /// evenly among them. Reads what the Forces pass read; run it before the velocities change.
        /// </summary>
        public static void MovingColliderLoads(in FluidConstants c, ReadOnlySpan<ColliderShape> colliders, int firstMoving, FluidParticles p,
            FluidScratch s, int start, int end, Span<float3> forces, Span<float3> torques)
        {
            if (c.Parameters.Solver != FluidSolverKind.WeaklyCompressible || firstMoving >= colliders.Length)
                return;
            if (c.IsPeriodic)
                MovingColliderLoads(c, colliders, firstMoving, p, s, start, end, forces, torques, new NearestImageOffset(c));
            else
                MovingColliderLoads(c, colliders, firstMoving, p, s, start, end, forces, torques, default(DirectOffset));
        }

        static void MovingColliderLoads<TOffset>(in FluidConstants c, ReadOnlySpan<ColliderShape> colliders, int firstMoving, FluidParticles p,
            FluidScratch s, int start, int end, Span<float3> forces, Span<float3> torques, TOffset offset) where TOffset : struct, IPairOffset
        {
            SphKernels k = c.Kernels;
            float alphaCh = 2f * c.EffectiveArtificialViscosity * c.Parameters.SpeedOfSound * k.H;
            // Force on the collider = −m·(ghost acceleration) = m²·C_spiky·κ∇·(ghost pair sum).
            float scale = c.Mass * c.Mass * k.SpikyGradientCoefficient * c.GradientCorrection;
            for (int i = start; i < end; i++)
            {
                float3 xi = p.Positions[i];
                var walls = FluidGhostWalls.Near(c, colliders, xi);
                int moving = walls.CollidersFrom(firstMoving);
                if (moving == 0)
                    continue;
                ReadOnlySpan<int> list = s.Neighbours.Slice(i * FluidScratch.MaxNeighbours, s.NeighbourCounts[i]);
                for (int w = 0; w < walls.Count; w++)
                {
                    if ((moving & (1 << w)) == 0)
                        continue;
                    float3 f = scale * GhostPressure(c, walls, colliders, p, s, list, xi, p.Velocities[i], s.Pressures[i], s.Densities[i], alphaCh,
                        1 << w, moving, offset);
                    int slot = walls.Collider(w) - firstMoving;
                    forces[slot] += f;
                    torques[slot] += math.cross(xi - colliders[walls.Collider(w)].Center, f);
                }
            }
        }

        /// <summary>
        /// The walls' ghosts' share of <see cref="PressureAcceleration"/>'s pair sum for a particle near <paramref name="walls"/>:
        /// the images of the particle and of each neighbour through every set of walls, each carrying its source's
        /// κⱼpⱼ/ρⱼ² extrapolated hydrostatically, max(0, κⱼpⱼ/ρⱼ² + g·(x_g − xⱼ)/ρⱼ) (κⱼ ≈ 1 in the extrapolation; Adami et al.
        /// 2012, eq. 27) where pⱼ &gt; 0 and 0 elsewhere, its density and its mirrored velocity for the artificial viscosity.
        /// In the pair sum's units, before its factor −m·C_spiky·κ∇. With <paramref name="only"/> ≠ 0, only the images through a
        /// set of walls that includes <paramref name="only"/>'s, each weighted 1/(the set's walls in <paramref name="shared"/>).
        /// </summary>
        static float3 GhostPressure<TOffset>(in FluidConstants c, in FluidGhostWalls walls, ReadOnlySpan<ColliderShape> colliders, FluidParticles p, FluidScratch s, ReadOnlySpan<int> list,
            float3 xi, float3 vi, float pi, float rhoi, float alphaCh, int only, int shared, TOffset offset) where TOffset : struct, IPairOffset
        {
            SphKernels k = c.Kernels;
            float3 g = c.Parameters.Gravity;
            float rho0 = c.Parameters.RestDensity, eta2 = 0.01f * k.H2, minDistance = 1e-6f * k.H;
            ReadOnlySpan<float3> x = p.Positions, velocities = p.Velocities;
            ReadOnlySpan<float> pressures = s.Pressures, densities = s.Densities;
            float3 sum = float3.zero;
            int subsets = walls.Subsets;
            for (int subset = 1; subset <= subsets; subset++)
            {
                if (only != 0 && (subset & only) == 0)
                    continue;
                float3 part = float3.zero;
                for (int m = -1; m < list.Length; m++)
                {
                    int j = m < 0 ? -1 : list[m];
                    float3 source = j < 0 ? float3.zero : -offset.Of(xi, x[j]);
                    float3 y = source;
                    float3 v = j < 0 ? vi : velocities[j];
                    if (!walls.Mirror(subset, xi, colliders, ref y, ref v))
                        continue;
                    float r2 = math.dot(y, y);
                    if (!(r2 < k.H2))
                        continue;
                    float r = math.sqrt(r2);
                    if (!(r > minDistance))
                        continue;
                    float rhoj = j < 0 ? rhoi : densities[j];
                    // Extrapolated only from a source under pressure: a lone particle or a thin film (p = 0) rests on the wall
                    // through its contact (FluidBoundary.ClampToDomain, ContactProjection), where the friction acts.
                    float pj = j < 0 ? pi : pressures[j];
                    float ghost = pj > 0f ? math.max(pj + math.dot(g, y - source) / math.max(rhoj, rho0), 0f) : 0f;
                    float3 rig = -y;
                    float scale = pi + ghost;
                    float approach = math.min(math.dot(vi - v, rig), 0f);
                    scale -= alphaCh * approach / ((rhoi + rhoj) * (r2 + eta2));
                    float hr = k.H - r;
                    if (only == 0)
                        sum += (scale * hr * hr / r) * rig;
                    else
                        part += (scale * hr * hr / r) * rig;
                }
                if (only != 0)
                    sum += part / WallCount(subset & shared);
            }
            return sum;
        }

        /// <summary>Walls in a set (bits of <paramref name="mask"/>; at most <see cref="FluidGhostWalls.MaxWalls"/>).</summary>
        static int WallCount(int mask)
        {
            int n = 0;
            for (int k = 0; k < FluidGhostWalls.MaxWalls; k++)
                n += (mask >> k) & 1;
            return n;
        }

        /// <summary>Flocking part of <see cref="Forces"/>: steer toward the kernel-weighted neighbour centroid, and away from neighbours closer than Δx.</summary>
        static void AddFlocking<TOffset>(in FluidConstants c, FluidParticles p, FluidScratch s, int i, ref float3 a, TOffset offset)
            where TOffset : struct, IPairOffset
        {
            SphKernels k = c.Kernels;
            FluidParameters prm = c.Parameters;
            float spacing = prm.ParticleSpacing;
            float3 xi = p.Positions[i];
            float3 centroid = float3.zero, separation = float3.zero;
            float weight = 0f;
            ReadOnlySpan<int> list = s.Neighbours.Slice(i * FluidScratch.MaxNeighbours, s.NeighbourCounts[i]);
            for (int n = 0; n < list.Length; n++)
            {
                float3 rij = offset.Of(xi, p.Positions[list[n]]);
                float3 xj = xi - rij;
                float r2 = math.lengthsq(rij);
                float w = k.Poly6(r2);
                centroid += w * xj;
                weight += w;
                float r = math.sqrt(r2);
                if (r < spacing && r > 0f)
                    separation += (spacing - r) / r * rij;
            }
            if (weight > 0f)
                a += prm.CohesionWeight * (centroid / weight - xi);
            a += prm.SeparationWeight * separation;
        }

        /// <summary>Akinci et al. 2013, eqs. 1–5: Σⱼ Kᵢⱼ·(m·C(r)·r̂ + (nᵢ − nⱼ)), Kᵢⱼ = 2ρ₀/(ρᵢ + ρⱼ); the acceleration is −γ times it.</summary>
        static float3 AkinciSum<TOffset>(in FluidConstants c, FluidParticles p, FluidScratch s, int i, TOffset offset)
            where TOffset : struct, IPairOffset
        {
            SphKernels k = c.Kernels;
            float m = c.Mass, rho0 = c.Parameters.RestDensity;
            float3 xi = p.Positions[i];
            float3 ni = s.VectorsB[i];
            float rhoi = s.Densities[i];
            float3 sum = float3.zero;
            ReadOnlySpan<int> list = s.Neighbours.Slice(i * FluidScratch.MaxNeighbours, s.NeighbourCounts[i]);
            for (int n = 0; n < list.Length; n++)
            {
                int j = list[n];
                float3 rij = offset.Of(xi, p.Positions[j]);
                float r = math.length(rij);
                if (!(r < k.H))
                    continue;
                float kij = 2f * rho0 / (rhoi + s.Densities[j]);
                float3 cohesion = r > 0f ? m * k.Cohesion(r) / r * rij : float3.zero;
                sum += kij * (cohesion + (ni - s.VectorsB[j]));
            }
            return sum;
        }

        /// <summary>A unit vector fixed by an unordered pair of ids, negated when the ids swap (so coincident pairs separate with zero net momentum).</summary>
        public static float3 CoincidentDirection(int idI, int idJ)
        {
            int lo = math.min(idI, idJ), hi = math.max(idI, idJ);
            uint hash = (uint)lo * 0x9E3779B1u ^ ((uint)hi + 0x7F4A7C15u) * 0x85EBCA77u;
            hash ^= hash >> 15;
            hash *= 0xC2B2AE3Du;
            hash ^= hash >> 13;
            // Spherical Fibonacci-like point from the hash: z in [−1, 1], angle in [0, 2π).
            float z = (hash & 0xFFFF) / 32767.5f - 1f;
            float phi = (hash >> 16) * (2f * math.PI / 65536f);
            float rxy = math.sqrt(math.max(0f, 1f - z * z));
            float3 d = new float3(rxy * math.cos(phi), rxy * math.sin(phi), z);
            return idI <= idJ ? d : -d;
        }

        /// <summary>
        /// One Jacobi iteration of implicit viscosity (backward Euler of Müller 2003's viscosity term, eq. 14):
        /// v⁽ᵏ⁺¹⁾ᵢ = (v⁰ᵢ + hν·Σⱼ sᵢⱼwᵢⱼ·v⁽ᵏ⁾ⱼ) / (1 + hν·Σⱼ sᵢⱼwᵢⱼ + hν·gᵢ), wᵢⱼ = m·2/(ρᵢ + ρⱼ)·∇²W_visc(rᵢⱼ)·κ_ν ≥ 0.
        /// Each iterate is a weighted average of v⁰ and neighbours, so it is bounded for any h·ν; with sᵢⱼ = (sᵢ + sⱼ)/2 the
        /// weights are symmetric and conserve momentum at convergence. sᵢ is the second-moment renormalization
        /// (<see cref="FluidConstants.ViscosityRenormalization"/>), which the first iteration of a substep computes into
        /// <see cref="FluidScratch.Floats"/> (cleared by <see cref="FluidPass.CopyVelocitiesToA"/>) using sᵢⱼ = sᵢ; later ones read
        /// it back. gᵢ is the no-slip walls' mirrored ghosts (MirroredGhosts). v⁰ is <see cref="FluidParticles.Velocities"/>.
        /// </summary>
        public static void ViscosityIteration(in FluidConstants c, ReadOnlySpan<ColliderShape> colliders, FluidParticles p, FluidScratch s,
            ReadOnlySpan<float3> source, Span<float3> destination, int start, int end, float h)
        {
            if (c.IsPeriodic)
                ViscosityIteration(c, colliders, p, s, source, destination, start, end, h, new NearestImageOffset(c));
            else
                ViscosityIteration(c, colliders, p, s, source, destination, start, end, h, default(DirectOffset));
        }

        static void ViscosityIteration<TOffset>(in FluidConstants c, ReadOnlySpan<ColliderShape> colliders, FluidParticles p, FluidScratch s,
            ReadOnlySpan<float3> source, Span<float3> destination, int start, int end, float h, TOffset offset) where TOffset : struct, IPairOffset
        {
            SphKernels k = c.Kernels;
            float hnu = h * c.Parameters.Viscosity;
            // wᵢⱼ = m·2/(ρᵢ + ρⱼ)·45/(πh⁶)·(h − r)·κ_ν: the constant factor is folded into hν.
            float hnuScaled = hnu * 2f * c.Mass * k.ViscosityLaplacianCoefficient * c.ViscosityCorrection;
            const int cap = FluidScratch.MaxNeighbours;
            ReadOnlySpan<float3> x = p.Positions, v0 = p.Velocities;
            ReadOnlySpan<float> densities = s.Densities;
            Span<float> scales = s.Floats;
            ReadOnlySpan<int> neighbours = s.Neighbours;
            float hk = k.H;
            float3 faces = c.FaceNoSlip, lo = c.Parameters.DomainMin, hi = c.Parameters.DomainMax;
            bool anyFace = math.any(faces > 0f);
            float colliderShare = c.Parameters.WallNoSlip;
            if (!(colliderShare > 0f))
                colliders = default;
            for (int i = start; i < end; i++)
            {
                float3 xi = x[i];
                float rhoi = densities[i];
                float si = scales[i];
                // Before the substep's first iteration the scale is 0: that iteration weighs every pair by sᵢ alone.
                bool first = !(si > 0f);
                float3 sum = float3.zero;
                float weight = 0f, moment = 0f;
                ReadOnlySpan<int> list = neighbours.Slice(i * cap, s.NeighbourCounts[i]);
                for (int n = 0; n < list.Length; n++)
                {
                    int j = list[n];
                    float r2 = math.lengthsq(offset.Of(xi, x[j]));
                    float w = math.max(hk - math.sqrt(r2), 0f) / (rhoi + densities[j]);
                    moment += w * r2;
                    w *= first ? 1f : 0.5f * (si + scales[j]);
                    sum += w * source[j];
                    weight += w;
                }
                var row = new ViscosityRow<TOffset>(x, densities, scales, list, xi, rhoi, first ? 0f : si, hk, offset);
                if (anyFace)
                    for (int a = 0; a < 3; a++)
                    {
                        float share = faces[a];
                        if (!(share > 0f))
                            continue;
                        float below = xi[a] - lo[a], above = hi[a] - xi[a];
                        float3 axis = float3.zero;
                        axis[a] = 1f;
                        if (below < hk)
                            MirroredGhosts(row, axis, below, share, ref weight, ref moment);
                        if (above < hk)
                            MirroredGhosts(row, -axis, above, share, ref weight, ref moment);
                    }
                for (int w = 0; w < colliders.Length; w++)
                    // Penetration with radius h reports depth = h − d for every point closer than h to the surface.
                    if (ParticleCollision.Penetration(colliders[w], xi, hk, out float3 normal, out float depth))
                        MirroredGhosts(row, normal, hk - depth, colliderShare, ref weight, ref moment);
                if (first)
                {
                    si = c.ViscosityRenormalization(moment);
                    scales[i] = si;
                    sum *= si;
                    weight *= si;
                }
                destination[i] = (v0[i] + hnuScaled * sum) / (1f + hnuScaled * weight);
            }
        }

        /// <summary>Particle i's neighbourhood for MirroredGhosts; <see cref="Si"/> is 0 in a substep's first iteration.</summary>
        readonly ref struct ViscosityRow<TOffset> where TOffset : struct, IPairOffset
        {
            public readonly ReadOnlySpan<float3> X;
            public readonly ReadOnlySpan<float> Densities, Scales;
            public readonly ReadOnlySpan<int> List;
            public readonly float3 Xi;
            public readonly float Rhoi, Si, H;
            public readonly TOffset Offset;

            public ViscosityRow(ReadOnlySpan<float3> x, ReadOnlySpan<float> densities, ReadOnlySpan<float> scales, ReadOnlySpan<int> list,
                float3 xi, float rhoi, float si, float h, TOffset offset)
            {
                X = x;
                Densities = densities;
                Scales = scales;
                List = list;
                Xi = xi;
                Rhoi = rhoi;
                Si = si;
                H = h;
                Offset = offset;
            }
        }

        /// <summary>
        /// The mirrored ghosts of a no-slip wall (Morris et al. 1997) at distance <paramref name="d"/> from particle i, unit normal
        /// <paramref name="n"/> into the fluid, no-slip share σ: particle i and each neighbour j at tⱼ = d + (xⱼ − xᵢ)·n &gt; 0 from the
        /// plane mirrored through it, so that the ghost of j is |rᵢ_g|² = |rᵢⱼ|² − ((xⱼ − xᵢ)·n)² + (d + tⱼ)² from i, with velocity
        /// −vᵢ·tⱼ/d; its pair term σwᵢ_g·(v_g − vᵢ) = −σwᵢ_g·(1 + tⱼ/d)·vᵢ adds only to i's weight. The ghosts also complete i's second
        /// moment (unscaled). d is taken at least 10⁻³h.
        /// </summary>
        static void MirroredGhosts<TOffset>(in ViscosityRow<TOffset> row, float3 n, float d, float share, ref float weight, ref float moment)
            where TOffset : struct, IPairOffset
        {
            d = math.max(d, 1e-3f * row.H);
            bool first = !(row.Si > 0f);
            // i's own ghost at 2d: tᵢ = d, so 1 + tᵢ/d = 2.
            MirroredGhost(row.H, 0f, 2f * d, 2f, share / (2f * row.Rhoi), first ? 1f : row.Si, ref weight, ref moment);
            for (int m = 0; m < row.List.Length; m++)
            {
                int j = row.List[m];
                float3 rij = row.Offset.Of(row.Xi, row.X[j]);
                float along = -math.dot(rij, n);
                float t = d + along;
                if (!(t > 0f))
                    continue;
                float pair = first ? 1f : 0.5f * (row.Si + row.Scales[j]);
                MirroredGhost(row.H, math.lengthsq(rij) - along * along, d + t, 1f + t / d, share / (row.Rhoi + row.Densities[j]), pair, ref weight, ref moment);
            }
        }

        /// <summary>One ghost at tangential distance² <paramref name="tangential2"/> and normal distance <paramref name="normal"/> from i: weight σ·(h − r)/(ρᵢ + ρⱼ) times <paramref name="factor"/> (1 + t/d) and the pair scale.</summary>
        static void MirroredGhost(float h, float tangential2, float normal, float factor, float shareOverDensity, float pair, ref float weight, ref float moment)
        {
            float r2 = tangential2 + normal * normal;
            if (!(r2 < h * h))
                return;
            float w = shareOverDensity * (h - math.sqrt(r2));
            moment += w * r2;
            weight += pair * factor * w;
        }

        /// <summary>
        /// XSPH smoothing (Monaghan 1989, eq. 4.3; the flocking rules' alignment) as a rate, in its symmetric form so that
        /// momentum is conserved: vᵢ += b·Σⱼ (2m/(ρᵢ + ρⱼ))·Wᵢⱼ·(vⱼ − vᵢ), b = 1 − e^(−rate·h) with rate =
        /// <see cref="FluidParameters.VelocitySmoothingRate"/>; inside the fluid Σⱼ (2m/(ρᵢ + ρⱼ))Wᵢⱼ ≈ 1, so vᵢ moves the
        /// fraction b of the way to its neighbours' mean, the same smoothing per second at any substep.
        /// </summary>
        public static void Alignment(in FluidConstants c, FluidParticles p, FluidScratch s, Span<float3> destination, int start, int end, float h)
        {
            SphKernels k = c.Kernels;
            float scale = (1f - math.exp(-c.Parameters.VelocitySmoothingRate * h)) * 2f * c.Mass;
            const int cap = FluidScratch.MaxNeighbours;
            for (int i = start; i < end; i++)
            {
                float3 xi = p.Positions[i], vi = p.Velocities[i];
                float rhoi = s.Densities[i];
                float3 sum = float3.zero;
                int count = s.NeighbourCounts[i];
                for (int n = 0; n < count; n++)
                {
                    int j = s.Neighbours[i * cap + n];
                    float w = k.Poly6(math.lengthsq(c.Offset(xi, p.Positions[j]))) / (rhoi + s.Densities[j]);
                    sum += w * (p.Velocities[j] - vi);
                }
                destination[i] = vi + scale * sum;
            }
        }

        /// <summary>
        /// Speed bound (counted), then xᵢ += h·vᵢ with the start position kept in <see cref="FluidScratch.Previous"/>,
        /// and the domain box. A velocity that is not finite marks the particle invalid (position NaN, velocity zero)
        /// so that no neighbour reads it and the next sort removes it.
        /// </summary>
        public static void Advect(in FluidConstants c, FluidParticles p, FluidScratch s, int start, int end, float h, ref FluidPassCounters counters)
        {
            for (int i = start; i < end; i++)
            {
                float3 v = p.Velocities[i];
                if (!math.all(math.isfinite(v)))
                {
                    s.Previous[i] = p.Positions[i];
                    p.Velocities[i] = float3.zero;
                    p.Positions[i] = new float3(float.NaN);
                    continue;
                }
                Move(c, p, s, i, v, h, ref counters);
            }
        }

        /// <summary>
        /// Keeps the start position in <see cref="FluidScratch.Previous"/>, bounds the speed (counted), moves the particle
        /// by h·v and keeps it in the domain box: the shared end of <see cref="Advect"/> and <see cref="Predict"/>.
        /// </summary>
        static void Move(in FluidConstants c, FluidParticles p, FluidScratch s, int i, float3 v, float h, ref FluidPassCounters counters)
        {
            float maxSpeed = c.Parameters.MaxSpeed;
            float3 x = p.Positions[i];
            s.Previous[i] = x;
            float speed2 = math.lengthsq(v);
            if (speed2 > maxSpeed * maxSpeed)
            {
                v *= maxSpeed / math.sqrt(speed2);
                counters.SpeedClamped++;
            }
            float3 start = x;
            x += h * v;
            FluidBoundary.ClampToDomain(c, ref x, ref v, start);
            p.Positions[i] = x;
            p.Velocities[i] = v;
        }

        /// <summary>
        /// Position-based: λᵢ = −Cᵢ / (Σₖ |∇ₖCᵢ|² + ε) with Cᵢ = ρᵢ/ρ₀ − 1 (Macklin &amp; Müller 2013, eqs. 1–11), the wall
        /// term included; Cᵢ is clamped at 0 so the free surface is never pulled together (the density clamp of the
        /// weakly compressible path). Reads <see cref="FluidScratch.Densities"/> from <see cref="Density"/>.
        /// </summary>
        public static void Lambda(in FluidConstants c, ReadOnlySpan<ColliderShape> colliders, FluidParticles p, FluidScratch s, int start, int end)
        {
            SphKernels k = c.Kernels;
            float invRho0 = 1f / c.Parameters.RestDensity;
            float mOverRho0 = c.Mass * invRho0;
            const int cap = FluidScratch.MaxNeighbours;
            for (int i = start; i < end; i++)
            {
                float constraint = s.Densities[i] * invRho0 - 1f;
                if (!(constraint > 0f))
                {
                    s.Pressures[i] = 0f;
                    continue;
                }
                float3 xi = p.Positions[i];
                FluidBoundary.Sample(c, colliders, xi, out _, out float3 push);
                float3 gradI = -push;
                float sumSq = 0f;
                int count = s.NeighbourCounts[i];
                for (int n = 0; n < count; n++)
                {
                    float3 rij = c.Offset(xi, p.Positions[s.Neighbours[i * cap + n]]);
                    float3 g = mOverRho0 * k.SpikyGradientScale(math.length(rij)) * rij;
                    gradI += g;
                    sumSq += math.lengthsq(g);
                }
                s.Pressures[i] = -constraint / (sumSq + math.lengthsq(gradI) + c.Relaxation);
            }
        }

        /// <summary>
        /// Position-based: Δxᵢ = (m/ρ₀)·Σⱼ (λᵢ + λⱼ + s_corr)·∇W(xᵢ − xⱼ) − λᵢ·Σ_walls G(d)·n (eqs. 12–14) into
        /// <see cref="FluidScratch.VectorsA"/>, with the artificial pressure s_corr = −k·λ₁·(W(r)/W(Δq))⁴, Δq = 0.2h
        /// (<see cref="FluidConstants.ArtificialPressureScale"/>).
        /// </summary>
        public static void Correction(in FluidConstants c, ReadOnlySpan<ColliderShape> colliders, FluidParticles p, FluidScratch s, int start, int end)
        {
            SphKernels k = c.Kernels;
            float mOverRho0 = c.Mass / c.Parameters.RestDensity;
            float artificial = c.ArtificialPressureScale, h2 = k.H2, inverseQ = 1f / (ArtificialPressureQ * k.H2);
            const int cap = FluidScratch.MaxNeighbours;
            for (int i = start; i < end; i++)
            {
                float3 xi = p.Positions[i];
                float li = s.Pressures[i];
                float3 dx = float3.zero;
                int count = s.NeighbourCounts[i];
                for (int n = 0; n < count; n++)
                {
                    int j = s.Neighbours[i * cap + n];
                    float3 rij = c.Offset(xi, p.Positions[j]);
                    float lij = li + s.Pressures[j];
                    if (artificial > 0f)
                    {
                        // (W(r)/W(Δq))⁴ = ((h² − r²)/(h² − Δq²))¹²
                        float t = math.max(h2 - math.lengthsq(rij), 0f) * inverseQ;
                        float t3 = t * t * t, t6 = t3 * t3;
                        lij -= artificial * (t6 * t6);
                    }
                    if (lij == 0f)
                        continue;
                    float r = math.length(rij);
                    if (r > 1e-6f * k.H)
                        dx += lij * k.SpikyGradientScale(r) * rij;
                    else
                        dx += lij * k.SpikyGradientCoefficient * k.H2 * CoincidentDirection(p.Ids[i], p.Ids[j]);
                }
                dx *= mOverRho0;
                if (li != 0f)
                {
                    FluidBoundary.Sample(c, colliders, xi, out _, out float3 push);
                    dx -= li * push;
                }
                s.VectorsA[i] = dx;
            }
        }

        /// <summary>h² − Δq² over h² for the artificial pressure's reference distance Δq = 0.2h (Macklin &amp; Müller 2013 use 0.1h–0.3h).</summary>
        public const float ArtificialPressureQ = 0.96f;

        /// <summary>Position-based: xᵢ += Δxᵢ, kept in the domain box.</summary>
        public static void ApplyCorrection(in FluidConstants c, FluidParticles p, FluidScratch s, int start, int end)
        {
            for (int i = start; i < end; i++)
            {
                float3 x = p.Positions[i] + s.VectorsA[i];
                float3 v = p.Velocities[i];
                FluidBoundary.ClampToDomain(c, ref x, ref v, s.Previous[i]);
                p.Positions[i] = x;
            }
        }

        /// <summary>Position-based: vᵢ = (xᵢ − x⁰ᵢ)/h, the velocity the constraint solve implies (eq. after Algorithm 1, line 21); across a periodic face the offset is the nearest image's.</summary>
        public static void VelocityFromPositions(in FluidConstants c, FluidParticles p, FluidScratch s, int start, int end, float h)
        {
            float invH = 1f / h;
            for (int i = start; i < end; i++)
                p.Velocities[i] = c.Offset(p.Positions[i], s.Previous[i]) * invH;
        }

        /// <summary>Position-based: v += h·g, x⁰ = x, x += h·v, kept in the domain box.</summary>
        public static void Predict(in FluidConstants c, FluidParticles p, FluidScratch s, int start, int end, float h, ref FluidPassCounters counters)
        {
            float3 g = c.Parameters.Gravity;
            for (int i = start; i < end; i++)
                Move(c, p, s, i, p.Velocities[i] + h * g, h, ref counters);
        }

        /// <summary>
        /// Colliders for slots [start, end): <see cref="ContactProjection.Project"/> with the particles as spheres of the
        /// wall distance, no bounce, Coulomb friction <see cref="FluidParameters.WallFriction"/>, starting from
        /// <see cref="FluidScratch.Previous"/> (contact normals go to <see cref="FluidScratch.VectorsA"/>).
        /// </summary>
        public static void Collide(in FluidConstants c, ReadOnlySpan<ColliderShape> colliders, FluidParticles p, FluidScratch s,
            int start, int end, float h, ref FluidPassCounters counters)
        {
            if (colliders.Length == 0 || end <= start)
                return;
            var settings = new ContactProjection.Settings
            {
                Radius = c.WallDistance,
                Friction = c.Parameters.WallFriction,
                Restitution = 0f,
                BounceThreshold = float.PositiveInfinity,
                MaxDepenetration = c.Parameters.MaxSpeed * h,
                Origin = float3.zero,
            };
            int n = end - start;
            counters.Contacts += ContactProjection.Project(s.Previous.Slice(start, n), p.Positions.Slice(start, n),
                p.Velocities.Slice(start, n), s.VectorsA.Slice(start, n), colliders, settings, h);
        }

        /// <summary>
        /// The moving colliders (index ≥ <paramref name="firstMoving"/>) for slots [start, end), after <see cref="Collide"/>: a
        /// particle closer than <see cref="FluidConstants.WallDistance"/> to one is put at that distance along its normal,
        /// and its velocity's normal part relative to the surface there, if approaching, is removed (free slip). The collider
        /// takes the opposite of the particle's momentum change, as a force over the substep of <paramref name="h"/> seconds
        /// (added to <paramref name="forces"/>, with its torque about the centre to <paramref name="torques"/>). In slot order.
        /// </summary>
        public static void CollideMoving(in FluidConstants c, ReadOnlySpan<ColliderShape> colliders, int firstMoving, FluidParticles p,
            int start, int end, float h, Span<float3> forces, Span<float3> torques, ref FluidPassCounters counters)
        {
            float radius = c.WallDistance, mass = c.Mass;
            for (int i = start; i < end; i++)
            {
                float3 x = p.Positions[i];
                if (!math.all(math.isfinite(x)))
                    continue;
                float3 v = p.Velocities[i];
                for (int w = firstMoving; w < colliders.Length; w++)
                {
                    if (!ParticleCollision.Penetration(colliders[w], x, radius, out float3 n, out float depth))
                        continue;
                    x += depth * n;
                    float approach = math.dot(v - colliders[w].VelocityAt(x - radius * n), n);
                    counters.Contacts++;
                    if (!(approach < 0f))
                        continue;
                    float3 dv = -approach * n;
                    v += dv;
                    float3 f = (-mass / h) * dv;
                    forces[w - firstMoving] += f;
                    torques[w - firstMoving] += math.cross(x - colliders[w].Center, f);
                }
                p.Positions[i] = x;
                p.Velocities[i] = v;
            }
        }

        /// <summary>
        /// Runs <paramref name="pass"/> on batch <paramref name="batch"/> of <paramref name="batches"/> equal ranges of the
        /// <paramref name="count"/> live particles (the sort runs whole on batch 0 and updates the count). The one dispatcher
        /// both the single-threaded step and the ECS jobs call.
        /// </summary>
        public static void Run(FluidPass pass, in FluidConstants c, ReadOnlySpan<ColliderShape> colliders, FluidParticles p, FluidScratch s,
            int batch, int batches, ref int count, float h, ref FluidPassCounters counters)
        {
            if (pass == FluidPass.Sort || pass == FluidPass.SortWithPrevious)
            {
                if (batch == 0)
                    count = FluidSolver.SortParticles(c, p, s, count, pass == FluidPass.SortWithPrevious, ref counters);
                return;
            }
            int start = (int)((long)count * batch / batches), end = (int)((long)count * (batch + 1) / batches);
            int n = end - start;
            switch (pass)
            {
                case FluidPass.Density: Density(c, colliders, p, s, start, end, ref counters); break;
                case FluidPass.DensityFromNeighbours: DensityFromNeighbours(c, colliders, p, s, start, end, ref counters); break;
                case FluidPass.SurfaceNormals: SurfaceNormals(c, p, s, start, end); break;
                case FluidPass.Forces: Forces(c, colliders, p, s, s.VectorsA, start, end, h, true); break;
                case FluidPass.CohesionForces: Forces(c, colliders, p, s, s.VectorsA, start, end, h, false); break;
                case FluidPass.CopyAToVelocities: s.VectorsA.Slice(start, n).CopyTo(p.Velocities.Slice(start, n)); break;
                case FluidPass.CopyVelocitiesToA:
                    p.Velocities.Slice(start, n).CopyTo(s.VectorsA.Slice(start, n));
                    // The viscosity renormalization of the coming iterations is not known yet (ViscosityIteration).
                    s.Floats.Slice(start, n).Clear();
                    break;
                case FluidPass.ViscosityAToB: ViscosityIteration(c, colliders, p, s, s.VectorsA, s.VectorsB, start, end, h); break;
                case FluidPass.ViscosityBToA: ViscosityIteration(c, colliders, p, s, s.VectorsB, s.VectorsA, start, end, h); break;
                case FluidPass.CopyBToVelocities: s.VectorsB.Slice(start, n).CopyTo(p.Velocities.Slice(start, n)); break;
                case FluidPass.Alignment: Alignment(c, p, s, s.VectorsA, start, end, h); break;
                case FluidPass.Advect: Advect(c, p, s, start, end, h, ref counters); break;
                case FluidPass.Predict: Predict(c, p, s, start, end, h, ref counters); break;
                case FluidPass.Lambda: Lambda(c, colliders, p, s, start, end); break;
                case FluidPass.Correction: Correction(c, colliders, p, s, start, end); break;
                case FluidPass.ApplyCorrection: ApplyCorrection(c, p, s, start, end); break;
                case FluidPass.VelocityFromPositions: VelocityFromPositions(c, p, s, start, end, h); break;
                case FluidPass.Collide: Collide(c, colliders, p, s, start, end, h, ref counters); break;
            }
        }
    }
}
