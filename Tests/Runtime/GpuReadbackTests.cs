using System.Collections;
using NUnit.Framework;
using SoftBodyDynamics.Compute;
using Unity.Collections;
using UnityEngine;
using UnityEngine.TestTools;

namespace SoftBodyDynamics.Tests.Runtime
{
    /// <summary>
    /// <see cref="GpuReadback{T}"/> keeps a completed read-back until it is taken: Unity disposes a request's own data the
    /// frame after it completes, and the fixed step that takes it may not run in that frame.
    /// </summary>
    public class GpuReadbackTests
    {
        [UnityTest]
        public IEnumerator Readback_IsKeptUntilTaken_FramesAfterItCompleted()
        {
            if (!SystemInfo.supportsAsyncGPUReadback)
                Assert.Ignore("this device has no asynchronous GPU read-back");
            var buffer = new GraphicsBuffer(GraphicsBuffer.Target.Structured, 4, sizeof(uint));
            var values = new NativeArray<uint>(new uint[] { 7, 11, 13, 4000000000 }, Allocator.Persistent);
            buffer.SetData(values, 0, 0, values.Length);
            values.Dispose();
            var readback = new GpuReadback<uint>();
            Assert.That(readback.Request(buffer), Is.True);
            Assert.That(readback.Request(buffer), Is.False, "one request in flight at a time");
            for (int frame = 0; frame < 600 && readback.Pending; frame++)
                yield return null;
            Assert.That(readback.Pending, Is.False, "the request completed within 600 frames");
            // Several frames after completion, when the request's own data is gone.
            for (int frame = 0; frame < 5; frame++)
                yield return null;
            Assert.That(readback.Arrived, Is.True);
            Assert.That(readback.Take().ToArray(), Is.EqualTo(new uint[] { 7, 11, 13, 4000000000 }));
            Assert.That(readback.Take().Length, Is.EqualTo(0), "taken once");
            readback.Dispose();
            buffer.Release();
        }
    }
}
