using System;
using System.Threading.Tasks;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Benchmarks.Scenarios
{
    /// <summary>Building blocks of the fluid scenarios: lattice blocks, bulk front, density statistics.</summary>
    public static class FluidScene
    {
        /// <summary>
        /// An ensemble of one scene: <paramref name="first"/> and <paramref name="members"/> − 1 copies made by <paramref name="make"/>
        /// from <paramref name="parameters"/> with ν scaled by 1 + k/100 (k = 1 … members − 1: water's ν is 1/2500 of the
        /// artificial viscosity's, no physical change, but a settled fluid's state is chaotic enough to move its metrics by
        /// several per cent), each run by <paramref name="run"/> in parallel.
        /// </summary>
        public static T[] Ensemble<T>(T first, int members, FluidParameters parameters, Func<FluidParameters, T> make, Action<T> run)
        {
            var ensemble = new T[Math.Max(1, members)];
            ensemble[0] = first;
            for (int k = 1; k < ensemble.Length; k++)
            {
                FluidParameters p = parameters;
                p.Viscosity *= 1f + 0.01f * k;
                ensemble[k] = make(p);
            }
            Parallel.For(0, ensemble.Length, k => run(ensemble[k]));
            return ensemble;
        }

        /// <summary>The mean of <paramref name="metric"/> over an ensemble's members and its standard deviation over them (NaN for one member).</summary>
        public static (double Mean, double Spread) MeanAndSpread<T>(T[] members, Func<T, double> metric)
        {
            double sum = 0, squares = 0;
            foreach (T m in members)
                sum += metric(m);
            double mean = sum / members.Length;
            foreach (T m in members)
                squares += (metric(m) - mean) * (metric(m) - mean);
            return (mean, members.Length > 1 ? Math.Sqrt(squares / (members.Length - 1)) : double.NaN);
        }

        /// <summary>A figure's series of a row's method: the text before its last comma (the whole method without one).</summary>
        public static string SeriesOf(string method)
        {
            int comma = method.LastIndexOf(',');
            return comma > 0 ? method.Substring(0, comma) : method;
        }

        /// <summary>A figure's point label of a row's method: the text after its last comma (empty without one).</summary>
        public static string PointOf(string method)
        {
            int comma = method.LastIndexOf(',');
            return comma > 0 ? method.Substring(comma + 1).Trim() : "";
        }

        /// <summary>One step of <paramref name="dt"/> seconds of the fluid in <paramref name="b"/>, without colliders.</summary>
        public static FluidStepReport Step(in FluidConstants c, FluidBuffers b, float dt) =>
            FluidSolver.Step(c, ReadOnlySpan<ColliderShape>.Empty, dt, b.Particles, b.Scratch, ref b.Status);

        /// <summary>
        /// Back to a run's start: the particles at <paramref name="initial"/> (all of it), at rest, ages and lifetimes 0, ids
        /// their slots, as if just spawned.
        /// </summary>
        public static void Restart(FluidBuffers b, float3[] initial)
        {
            int n = initial.Length;
            Array.Copy(initial, b.Positions, n);
            Array.Clear(b.Velocities, 0, n);
            Array.Clear(b.Ages, 0, n);
            Array.Clear(b.Lifetimes, 0, n);
            for (int i = 0; i < n; i++)
                b.Ids[i] = i;
            b.Status = new FluidStatus { Count = n, NextId = n, Spawned = n };
        }

        /// <summary>Fills the box [<paramref name="lo"/>, <paramref name="hi"/>) with a cubic lattice at the fluid's spacing (first point half a spacing in) and returns the count.</summary>
        public static int FillBlock(FluidBuffers b, float3 lo, float3 hi, float spacing)
        {
            int n = b.Status.Count;
            int nx = (int)math.floor((hi.x - lo.x) / spacing + 1e-3f);
            int ny = (int)math.floor((hi.y - lo.y) / spacing + 1e-3f);
            int nz = (int)math.floor((hi.z - lo.z) / spacing + 1e-3f);
            for (int z = 0; z < nz; z++)
            for (int y = 0; y < ny; y++)
            for (int x = 0; x < nx && n < b.Capacity; x++)
            {
                b.Positions[n] = lo + (new float3(x, y, z) + 0.5f) * spacing;
                b.Velocities[n] = float3.zero;
                b.Ages[n] = 0f;
                b.Lifetimes[n] = 0f;
                b.Ids[n] = b.Status.NextId++;
                n++;
            }
            b.Status.Spawned += n - b.Status.Count;
            b.Status.Count = n;
            return n;
        }

        /// <summary>
        /// The fluid of <paramref name="parameters"/> at <paramref name="spacing"/> in the box [0, <paramref name="domainMax"/>]
        /// under Earth gravity (−9.81 m/s² along y), its buffers sized for and filled with the lattice block [0, <paramref name="block"/>).
        /// </summary>
        public static FluidBuffers BlockInBox(FluidParameters parameters, float spacing, float3 domainMax, float3 block, out FluidConstants constants)
        {
            parameters.ParticleSpacing = spacing;
            parameters.DomainMin = float3.zero;
            parameters.DomainMax = domainMax;
            parameters.Gravity = new float3(0f, -9.81f, 0f);
            constants = new FluidConstants(parameters);
            var b = new FluidBuffers(BlockCount(float3.zero, block, spacing), constants.Grid);
            FillBlock(b, float3.zero, block, spacing);
            return b;
        }

        /// <summary>Lattice points of a block (for sizing buffers).</summary>
        public static int BlockCount(float3 lo, float3 hi, float spacing) =>
            (int)math.floor((hi.x - lo.x) / spacing + 1e-3f) * (int)math.floor((hi.y - lo.y) / spacing + 1e-3f) * (int)math.floor((hi.z - lo.z) / spacing + 1e-3f);

        /// <summary>
        /// Leading edge (m) along +x of the bulk: the largest x among particles with at least
        /// <paramref name="minNeighbours"/> neighbours in the last density pass, plus half a spacing (the edge of its
        /// volume). Isolated splash droplets ahead of the front do not count.
        /// </summary>
        public static double BulkFront(FluidBuffers b, float spacing, int minNeighbours)
        {
            double front = double.NegativeInfinity;
            for (int i = 0; i < b.Status.Count; i++)
                if (b.NeighbourCounts[i] >= minNeighbours)
                    front = Math.Max(front, b.Positions[i].x);
            return front + 0.5 * spacing;
        }

        /// <summary>
        /// Height (m) of the bulk at the wall x = 0: the largest y among particles with at least <paramref name="minNeighbours"/>
        /// neighbours and x below <paramref name="band"/>, plus half a spacing; 0 when none is there.
        /// </summary>
        public static double BulkHeightAtWall(FluidBuffers b, float spacing, int minNeighbours, float band)
        {
            double top = double.NegativeInfinity;
            for (int i = 0; i < b.Status.Count; i++)
                if (b.NeighbourCounts[i] >= minNeighbours && b.Positions[i].x < band)
                    top = Math.Max(top, b.Positions[i].y);
            return double.IsNegativeInfinity(top) ? 0.0 : top + 0.5 * spacing;
        }

        /// <summary>Mean |ρ/ρ₀ − 1| over particles with at least <paramref name="minNeighbours"/> neighbours (the last density pass).</summary>
        public static double MeanBulkDensityError(FluidBuffers b, float restDensity, int minNeighbours)
        {
            double sum = 0;
            int count = 0;
            for (int i = 0; i < b.Status.Count; i++)
            {
                if (b.NeighbourCounts[i] < minNeighbours)
                    continue;
                sum += Math.Abs(b.Densities[i] / restDensity - 1.0);
                count++;
            }
            return count > 0 ? sum / count : double.NaN;
        }

        /// <summary>Linear interpolation of the samples (xs ascending) at <paramref name="x"/>, clamped to the ends.</summary>
        public static double Interpolate(double[] xs, double[] ys, int count, double x)
        {
            if (count == 0)
                return double.NaN;
            if (x <= xs[0])
                return ys[0];
            for (int i = 1; i < count; i++)
                if (x <= xs[i])
                    return ys[i - 1] + (ys[i] - ys[i - 1]) * (x - xs[i - 1]) / (xs[i] - xs[i - 1]);
            return ys[count - 1];
        }
    }
}
