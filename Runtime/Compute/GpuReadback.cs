using System;
using Unity.Collections;
using UnityEngine;
using UnityEngine.Rendering;

namespace SoftBodyDynamics.Compute
{
    /// <summary>
    /// An asynchronous read-back of a <see cref="GraphicsBuffer"/> that is never lost. A completed
    /// <see cref="AsyncGPUReadbackRequest"/> is readable only in the frame it completes and is disposed of in the next
    /// (https://docs.unity3d.com/ScriptReference/Rendering.AsyncGPUReadbackRequest.html), while the fixed step that asked
    /// for it does not run every frame; so the request's callback, which Unity calls in that frame, copies the data into an
    /// array this object owns, and the fixed step takes it whenever it next runs. One request in flight at a time.
    /// </summary>
    public sealed class GpuReadback<T> : IDisposable where T : struct
    {
        readonly Action<AsyncGPUReadbackRequest> m_OnDone;
        NativeArray<T> m_Data;
        int m_Length;
        bool m_Pending, m_Arrived, m_Disposed;

        public GpuReadback() => m_OnDone = OnDone;

        /// <summary>A request is in flight.</summary>
        public bool Pending => m_Pending;

        /// <summary>Data arrived that <see cref="Take"/> has not taken yet.</summary>
        public bool Arrived => m_Arrived;

        /// <summary>Asks for <paramref name="buffer"/>'s contents unless a request is in flight (returns whether it asked).</summary>
        public bool Request(GraphicsBuffer buffer)
        {
            if (m_Pending || m_Disposed || buffer == null)
                return false;
            m_Pending = true;
            // https://docs.unity3d.com/ScriptReference/Rendering.AsyncGPUReadback.Request.html (the callback form).
            AsyncGPUReadback.Request(buffer, m_OnDone);
            return true;
        }

        /// <summary>The data that arrived, once (empty when none did since the last call).</summary>
        public ReadOnlySpan<T> Take()
        {
            if (!m_Arrived)
                return ReadOnlySpan<T>.Empty;
            m_Arrived = false;
            return m_Data.AsReadOnlySpan().Slice(0, m_Length);
        }

        void OnDone(AsyncGPUReadbackRequest request)
        {
            m_Pending = false;
            if (m_Disposed || request.hasError)
                return;
            NativeArray<T> source = request.GetData<T>();
            if (!m_Data.IsCreated || m_Data.Length < source.Length)
            {
                if (m_Data.IsCreated)
                    m_Data.Dispose();
                m_Data = new NativeArray<T>(source.Length, Allocator.Persistent, NativeArrayOptions.UninitializedMemory);
            }
            NativeArray<T>.Copy(source, 0, m_Data, 0, source.Length);
            m_Length = source.Length;
            m_Arrived = true;
        }

        /// <summary>Frees the copy; a request still in flight completes into nothing.</summary>
        public void Dispose()
        {
            m_Disposed = true;
            m_Arrived = false;
            if (m_Data.IsCreated)
                m_Data.Dispose();
        }
    }
}
