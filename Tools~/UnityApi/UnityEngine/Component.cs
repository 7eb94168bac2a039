namespace UnityEngine
{
    // https://docs.unity3d.com/ScriptReference/Component.html
    public class Component : Object
    {
        // https://docs.unity3d.com/ScriptReference/Component-transform.html
        public Transform transform => throw null;

        // https://docs.unity3d.com/ScriptReference/Component-gameObject.html
        public GameObject gameObject => throw null;

        // https://docs.unity3d.com/ScriptReference/Component.GetComponent.html
        public T GetComponent<T>() => throw null;
    }

    // https://docs.unity3d.com/ScriptReference/Behaviour.html
    public class Behaviour : Component
    {
    }

    // https://docs.unity3d.com/ScriptReference/MonoBehaviour.html
    public class MonoBehaviour : Behaviour
    {
    }
}
