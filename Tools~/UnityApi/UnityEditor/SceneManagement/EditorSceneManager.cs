using UnityEngine.SceneManagement;

namespace UnityEditor.SceneManagement
{
    // https://docs.unity3d.com/ScriptReference/SceneManagement.EditorSceneManager.html
    public sealed class EditorSceneManager : SceneManager
    {
        // https://docs.unity3d.com/ScriptReference/SceneManagement.EditorSceneManager.NewScene.html
        public static Scene NewScene(NewSceneSetup setup, NewSceneMode mode = NewSceneMode.Single) => throw null;
        // https://docs.unity3d.com/ScriptReference/SceneManagement.EditorSceneManager.SaveScene.html
        public static bool SaveScene(Scene scene, string dstScenePath = "", bool saveAsCopy = false) => throw null;
        // https://docs.unity3d.com/ScriptReference/SceneManagement.EditorSceneManager.CloseScene.html
        public static bool CloseScene(Scene scene, bool removeScene) => throw null;
        // https://docs.unity3d.com/ScriptReference/SceneManagement.EditorSceneManager.SaveCurrentModifiedScenesIfUserWantsTo.html
        public static bool SaveCurrentModifiedScenesIfUserWantsTo() => throw null;
    }

    // https://docs.unity3d.com/ScriptReference/SceneManagement.NewSceneSetup.html (values UNCONFIRMED; names from the page)
    public enum NewSceneSetup
    {
        EmptyScene = 0,
        DefaultGameObjects = 1,
    }

    // https://docs.unity3d.com/ScriptReference/SceneManagement.NewSceneMode.html (values UNCONFIRMED; names from the page)
    public enum NewSceneMode
    {
        Single = 0,
        Additive = 1,
    }
}
