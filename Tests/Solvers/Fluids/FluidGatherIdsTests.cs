using System;
using System.Collections.Generic;
using NUnit.Framework;
using SoftBodyDynamics.Solvers;
using Unity.Mathematics;

namespace SoftBodyDynamics.Tests.Solvers
{
    /// <summary>Tracking gathered particles (one entity each) through a frame that sorts, removes and adds particles.</summary>
    public class FluidGatherIdsTests
    {
        [Test]
        public void GatheredParticles_KeepTheirIdentity_NewOnesGetFreshIds_AndRemovedOnesAreReported()
        {
            var c = new FluidConstants(FluidTestScenes.Water(0.02f, new float3(-0.2f, 0f, -0.2f), new float3(0.2f, 0.5f, 0.2f)));
            var b = new FluidBuffers(2000, c.Grid);
            FluidTapSettings s = FluidTapSettings.Default;
            s.Position = new float3(0f, 0.4f, 0f);
            s.Rotation = quaternion.AxisAngle(new float3(1f, 0f, 0f), math.PI / 2f);
            s.Rate = 400f;
            var taps = new[] { new FluidTapInstance { Settings = s } };
            var drains = new[] { new FluidDrain { Shape = ColliderShape.Box(new float3(0f, 0.02f, 0f), quaternion.identity, new float3(0.2f, 0.03f, 0.2f)) } };
            // The "entities": a dictionary id → (position, velocity), as gameplay would see them.
            var entities = new Dictionary<int, (float3 x, float3 v)>();
            var realIds = new int[2000];
            var gatherOf = new int[2000];
            var survived = new byte[2000];
            for (int frame = 0; frame < 90; frame++)
            {
                // Gather: pack the entities in an arbitrary (reverse id) order; at frame 40 gameplay destroys one.
                if (frame == 40)
                {
                    Assert.That(entities.Count, Is.GreaterThan(0));
                    foreach (int id in entities.Keys)
                    {
                        entities.Remove(id);
                        break;
                    }
                }
                var order = new List<int>(entities.Keys);
                order.Sort((x, y) => y.CompareTo(x));
                for (int k = 0; k < order.Count; k++)
                {
                    b.Positions[k] = entities[order[k]].x;
                    b.Velocities[k] = entities[order[k]].v;
                    b.Lifetimes[k] = 0f;
                    b.Ids[k] = order[k];
                }
                long killedBefore = b.Status.Killed;
                int realNext = FluidGatherIds.Begin(b.Particles, realIds, order.Count, ref b.Status);
                if (frame == 40)
                    Assert.AreEqual(killedBefore + 1, b.Status.Killed, "an entity destroyed by gameplay counts as killed");
                FluidFrame.Advance(c, default, drains, taps, default, 0, 1f / 60f, b.Particles, b.Scratch, ref b.Status);
                int created = FluidGatherIds.End(b.Particles, realIds, order.Count, realNext, gatherOf, survived, ref b.Status);
                // Write back: survivors keep their id and their entity; the others are destroyed; new ids are fresh.
                var next = new Dictionary<int, (float3 x, float3 v)>();
                int seenNew = 0;
                for (int slot = 0; slot < b.Status.Count; slot++)
                {
                    int g = gatherOf[slot];
                    if (g >= 0)
                        Assert.AreEqual(order[g], b.Ids[slot], "a survivor keeps the id of the entity it came from");
                    else
                    {
                        Assert.That(b.Ids[slot], Is.GreaterThanOrEqualTo(realNext));
                        Assert.IsFalse(entities.ContainsKey(b.Ids[slot]));
                        seenNew++;
                    }
                    next.Add(b.Ids[slot], (b.Positions[slot], b.Velocities[slot]));
                }
                Assert.AreEqual(created, seenNew);
                FluidStatus st = b.Status;
                Assert.AreEqual(st.Spawned - st.Killed - st.Expired - st.Invalid, st.Count, $"frame {frame}");
                entities = next;
            }
            Assert.That(b.Status.Killed, Is.GreaterThan(1), "the drain removed particles too");
        }
    }
}
