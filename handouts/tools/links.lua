-- Links in the HTML pages: a link to another handout (NAME.md) goes to its page (NAME.html);
-- a relative link to any other file is rebased from handouts/ to the page's folder with the
-- metadata field `rebase` (a prefix, set by make_html.py). Images are embedded, so left alone.
local rebase = ""

local function is_relative(target)
    return not target:match("^%a[%w+.-]*:") and not target:match("^#") and not target:match("^/")
end

return {
    {Meta = function(meta)
        if meta.rebase then rebase = pandoc.utils.stringify(meta.rebase) end
    end},
    {Link = function(link)
        if not is_relative(link.target) then return nil end
        local path, anchor = link.target:match("^([^#]*)(#?.*)$")
        if path:match("^[^/]+%.md$") then
            link.target = path:gsub("%.md$", ".html") .. anchor
        else
            link.target = rebase .. path .. anchor
        end
        return link
    end},
}
