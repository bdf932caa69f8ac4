-- conf.lua: LÖVE reads this before main.lua. `--headless` turns the window, graphics and sound off,
-- so the game can train on a machine without a display (CI runs it that way).
local headless = false
for _, a in ipairs(arg or {}) do
  if a == "--headless" then headless = true end
end

function love.conf(t)
  t.identity = "verve-rays"             -- save directory: love.filesystem.getSaveDirectory()
  t.version = "11.4"
  t.window.title = "Verve: NPCs that see with rays"
  t.window.width, t.window.height = 820, 540
  t.modules.audio, t.modules.sound = false, false
  t.modules.joystick = false
  if headless then
    t.window = false
    t.modules.window, t.modules.graphics = false, false
  end
end
