using NUnit.Framework;
using SoftBodyDynamics.Solvers;

namespace SoftBodyDynamics.Tests.Solvers
{
    /// <summary>The GPU buffers' capacity doubles until it holds what is asked, exactly, up to int.MaxValue.</summary>
    public class FluidComputeLayoutTests
    {
        [TestCase(1, 1, 1)]
        [TestCase(0, 5, 8)]
        [TestCase(1000, 1001, 2000)]
        [TestCase(16777217, 33554434, 33554434)]
        [TestCase(1 << 30, (1 << 30) + 1, int.MaxValue)]
        public void GrownCapacity_DoublesUntilItHoldsTheRequest(int current, int wanted, int expected)
        {
            // Above 2²⁴ a float min would round 33554434 (and its double) to a smaller capacity than asked for.
            Assert.That(FluidComputeLayout.GrownCapacity(current, wanted), Is.EqualTo(expected));
        }
    }
}
