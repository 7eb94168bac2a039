using NUnit.Framework;
using SoftBodyDynamics.Benchmarks.Scenarios;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Tests.Solvers
{
    /// <summary>Overlapping clusters let a body bend locally instead of moving as one block.</summary>
    public class ShapeMatchingClusterTests
    {
        /// <summary>
        /// A 1.2 m bar balanced on a narrow support sags at both ends. With one cluster the goals are a
        /// rigid copy of the whole bar, so its ends cannot droop relative to its middle beyond the
        /// softness α allows; with small overlapping clusters each region only keeps its own shape and
        /// the bar bends: its droop must be clearly larger (an ordering, as in MuJoCo's tests).
        /// </summary>
        [Test]
        public void SmallerClusters_BendMoreUnderLoad()
        {
            float Droop(int clusterSize)
            {
                var model = LatticeBody.Create(new int3(13, 2, 2), 0.1f, clusterSize, 1f);
                var p = ShapeMatchingParameters.Default;
                p.Mode = ShapeMatchingMode.Rigid;
                p.Body.SleepSpeed = 0f;
                var body = new ShapeMatchingInstance(model, p, new float3(0f, 0.3f, 0f), quaternion.identity);
                var support = new[] { ColliderShape.Box(new float3(0f, 0f, 0f), quaternion.identity, new float3(0.12f, 0.2f, 0.5f)) };
                for (int step = 0; step < 240; step++)
                    body.Step(1f / 60f, support);
                // Middle height minus the mean height of the two end columns.
                float middle = 0f, ends = 0f;
                int nm = 0, ne = 0;
                for (int i = 0; i < body.Positions.Length; i++)
                {
                    float restX = model.RestPositions[i].x;
                    if (math.abs(restX) < 0.05f) { middle += body.Positions[i].y; nm++; }
                    if (math.abs(restX) > 0.55f) { ends += body.Positions[i].y; ne++; }
                }
                return middle / nm - ends / ne;
            }
            float oneCluster = Droop(13), overlapping = Droop(3);
            Assert.That(overlapping, Is.GreaterThan(2f * oneCluster + 0.01f), $"droop {overlapping} m vs {oneCluster} m");
        }

        [Test]
        public void ClusterWeights_SplitEachParticlesMassOverItsClusters()
        {
            var model = LatticeBody.Create(new int3(6, 3, 3), 0.1f, 3, 1f);
            Assert.That(model.ClusterCount, Is.GreaterThan(1));
            var counts = new int[model.ParticleCount];
            foreach (int i in model.ClusterParticles)
                counts[i]++;
            for (int i = 0; i < counts.Length; i++)
            {
                Assert.That(counts[i], Is.GreaterThan(0), "every particle is in a cluster");
                Assert.That(model.InverseClusterCounts[i], Is.EqualTo(1f / counts[i]));
            }
            // Σ wᵢ over a particle's clusters is its mass: the split keeps the body's mass.
            var massInClusters = new float[model.ParticleCount];
            for (int k = 0; k < model.ClusterParticles.Length; k++)
                massInClusters[model.ClusterParticles[k]] += model.ClusterWeights[k];
            for (int i = 0; i < counts.Length; i++)
                Assert.That(massInClusters[i], Is.EqualTo(model.Masses[i]).Within(1e-6f * model.Masses[i] * counts[i]));
        }
    }
}
