// SPDX-FileCopyrightText: 2026 The Crumple authors
// SPDX-License-Identifier: MIT
#include <crumple/fem_import/TetgenOutput.h>

#include <charconv>
#include <cmath>
#include <sstream>
#include <string>

namespace crumple::fem
{

namespace
{

// The non-empty, comment-free lines of a tetgen output file, split into fields.
class TetgenFile
{
  public:
    static TetgenFile FromText(std::string_view inText, std::string inName)
    {
        TetgenFile file;
        file.mName = std::move(inName);
        std::istringstream lines{std::string(inText)};
        std::string line;
        while (std::getline(lines, line))
        {
            std::istringstream fields(line.substr(0, line.find('#')));
            std::vector<std::string> row;
            for (std::string field; fields >> field;)
                row.push_back(field);
            if (!row.empty())
                file.mRows.push_back(std::move(row));
        }
        return file;
    }

    /// Fields inFirst .. inFirst + inCount - 1 of row inRow as numbers; false when missing or malformed.
    template <class T>
    bool Numbers(std::size_t inRow, std::size_t inFirst, std::size_t inCount, T* outValues) const
    {
        if (inRow >= mRows.size() || mRows[inRow].size() < inFirst + inCount)
            return false;
        for (std::size_t field = 0; field < inCount; ++field)
        {
            const std::string& text = mRows[inRow][inFirst + field];
            const char* end = text.data() + text.size();
            const std::from_chars_result result = std::from_chars(text.data(), end, outValues[field]);
            if (result.ec != std::errc() || result.ptr != end)
                return false;
        }
        return true;
    }

    std::size_t GetRowCount() const { return mRows.size(); }

    Error Corrupt(const std::string& inWhat) const
    {
        return MakeError(EError::CorruptData, "tetgen output " + mName + ": " + inWhat);
    }

  private:
    std::string mName;
    std::vector<std::vector<std::string>> mRows;
};

// Reads <name>.1.node: "count 3 #attributes #markers", then "index x y z ...". outBase is the first index (0
// with -z, 1 without), which the .ele file uses too.
Status ReadNodes(const TetgenFile& inFile, std::vector<Vec3>& outNodes, long long& outBase)
{
    long long header[2] = {};
    if (!inFile.Numbers(0, 0, 2, header) || header[1] != 3 || header[0] < 4 ||
        header[0] > TetMesh::cMaxCount || inFile.GetRowCount() < static_cast<std::size_t>(header[0]) + 1)
        return inFile.Corrupt("bad header or too few lines");
    outNodes.resize(static_cast<std::size_t>(header[0]));
    for (std::size_t node = 0; node < outNodes.size(); ++node)
    {
        long long index = 0;
        double xyz[3] = {};
        if (!inFile.Numbers(node + 1, 0, 1, &index) || !inFile.Numbers(node + 1, 1, 3, xyz))
            return inFile.Corrupt("bad line for node " + std::to_string(node));
        if (node == 0)
            outBase = index;
        if (index != outBase + static_cast<long long>(node) || (outBase != 0 && outBase != 1))
            return inFile.Corrupt("node numbers do not count up from 0 or 1");
        // intent: from_chars reads "nan" and "inf" as numbers; a mesh refuses them later, but this names the line
        if (!std::isfinite(xyz[0]) || !std::isfinite(xyz[1]) || !std::isfinite(xyz[2]))
            return inFile.Corrupt("node " + std::to_string(node) + " is not finite");
        outNodes[node] = Vec3(xyz[0], xyz[1], xyz[2]);
    }
    return Status::Ok();
}

// Reads <name>.1.ele: "count 4 #attributes", then "index n0 n1 n2 n3 ...", indices from inBase.
Status ReadElements(const TetgenFile& inFile, long long inBase, int inNodeCount,
                    std::vector<TetIndices>& outTets)
{
    long long header[2] = {};
    if (!inFile.Numbers(0, 0, 2, header) || header[1] != 4 || header[0] < 1 ||
        header[0] > TetMesh::cMaxCount || inFile.GetRowCount() < static_cast<std::size_t>(header[0]) + 1)
        return inFile.Corrupt("bad header or too few lines (expected 4 nodes per element)");
    outTets.resize(static_cast<std::size_t>(header[0]));
    for (std::size_t tet = 0; tet < outTets.size(); ++tet)
    {
        long long corners[5] = {};
        if (!inFile.Numbers(tet + 1, 0, 5, corners) || corners[0] != inBase + static_cast<long long>(tet))
            return inFile.Corrupt("bad line for element " + std::to_string(tet));
        for (int corner = 0; corner < 4; ++corner)
        {
            const long long node = corners[corner + 1] - inBase;
            if (node < 0 || node >= inNodeCount)
                return inFile.Corrupt("element " + std::to_string(tet) + " names a node out of range");
            outTets[tet][corner] = static_cast<int>(node);
        }
    }
    return Status::Ok();
}

} // namespace

Result<TetgenOutput> ParseTetgenOutput(std::string_view inNodeText, std::string_view inElementText)
{
    TetgenOutput output;
    long long base = 0;
    if (Status read = ReadNodes(TetgenFile::FromText(inNodeText, "surface.1.node"), output.mNodes, base); !read)
        return read.GetError();
    if (Status read = ReadElements(TetgenFile::FromText(inElementText, "surface.1.ele"), base,
                                   static_cast<int>(output.mNodes.size()), output.mTets);
        !read)
        return read.GetError();
    return output;
}

} // namespace crumple::fem
