namespace UnityEngine
{
    // https://docs.unity3d.com/ScriptReference/ISerializationCallbackReceiver.html
    public interface ISerializationCallbackReceiver
    {
        // https://docs.unity3d.com/ScriptReference/ISerializationCallbackReceiver.OnBeforeSerialize.html
        void OnBeforeSerialize();
        // https://docs.unity3d.com/ScriptReference/ISerializationCallbackReceiver.OnAfterDeserialize.html
        void OnAfterDeserialize();
    }
}
