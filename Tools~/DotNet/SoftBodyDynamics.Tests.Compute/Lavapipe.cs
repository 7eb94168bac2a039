using NUnit.Framework;
using SoftBodyDynamics.Lavapipe;

namespace SoftBodyDynamics.Tests.Compute
{
    /// <summary>
    /// One lavapipe device and one compiled FluidSolver.compute for the whole run. The device runs under the Khronos
    /// validation layer (when installed) so a binding or layout mistake fails the test that made it.
    /// </summary>
    [SetUpFixture]
    public sealed class Lavapipe
    {
        public static LavapipeDevice Device { get; private set; }
        public static LavapipeComputeShader FluidShader { get; private set; }

        [OneTimeSetUp]
        public void Start()
        {
            System.Environment.SetEnvironmentVariable("VKH_VALIDATION", "1");
            Device = new LavapipeDevice();
            FluidShader = new LavapipeComputeShader(Device, LavapipeFluidSolver.ComputePath());
            TestContext.Progress.WriteLine($"device: {Device.DeviceName}, validation layer: {(Device.ValidationEnabled ? "on" : "not installed")}");
        }

        [OneTimeTearDown]
        public void Stop()
        {
            FluidShader?.Dispose();
            Device?.Dispose();
        }

        /// <summary>No validation message so far.</summary>
        public static void AssertValid() =>
            Assert.That(Device.ValidationMessages, Is.Zero, "the Vulkan validation layer reported problems (see the test output)");
    }
}
