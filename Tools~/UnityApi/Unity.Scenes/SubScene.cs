using UnityEngine;

namespace Unity.Scenes
{
    // https://docs.unity3d.com/Packages/com.unity.entities@1.4/api/Unity.Scenes.SubScene.html
    // source: Unity.Scenes/SubScene.cs (1.4.2): [ExecuteAlways, DisallowMultipleComponent] public class SubScene : MonoBehaviour
    public class SubScene : MonoBehaviour
    {
        // ...Unity.Scenes.SubScene.html#Unity_Scenes_SubScene_AutoLoadScene  (a public field)
        public bool AutoLoadScene;

        // ...Unity.Scenes.SubScene.html#Unity_Scenes_SubScene_SceneAsset  (#if UNITY_EDITOR in the source)
        public UnityEditor.SceneAsset SceneAsset { get => throw null; set => throw null; }
    }
}
