namespace UnityEngine
{
    // https://docs.unity3d.com/ScriptReference/Camera.html
    public sealed class Camera : Behaviour
    {
        // https://docs.unity3d.com/ScriptReference/Camera-fieldOfView.html
        public float fieldOfView { get => throw null; set => throw null; }
    }
}
