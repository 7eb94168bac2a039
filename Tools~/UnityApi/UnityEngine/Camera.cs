namespace UnityEngine
{
    // https://docs.unity3d.com/ScriptReference/Camera.html
    public sealed class Camera : Behaviour
    {
        // https://docs.unity3d.com/ScriptReference/Camera-fieldOfView.html
        public float fieldOfView { get => throw null; set => throw null; }

        // https://docs.unity3d.com/ScriptReference/Camera-nearClipPlane.html (checked: UnityCsReference 6000.0.78f1 Runtime/Export/Camera/Camera.bindings.cs)
        public float nearClipPlane { get => throw null; set => throw null; }

        // https://docs.unity3d.com/ScriptReference/Camera-farClipPlane.html (same source)
        public float farClipPlane { get => throw null; set => throw null; }

        // https://docs.unity3d.com/ScriptReference/Camera-worldToCameraMatrix.html (same source; view space looks down -z)
        public Matrix4x4 worldToCameraMatrix { get => throw null; set => throw null; }

        // https://docs.unity3d.com/ScriptReference/Camera-cameraType.html (same source)
        public CameraType cameraType { get => throw null; set => throw null; }
    }

    // https://docs.unity3d.com/ScriptReference/CameraType.html (checked: UnityCsReference 6000.0.78f1 Runtime/Export/Graphics/GraphicsEnums.cs)
    [System.Flags]
    public enum CameraType
    {
        Game = 1,
        SceneView = 2,
        Preview = 4,
        VR = 8,
        Reflection = 16,
    }
}
